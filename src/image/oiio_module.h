// Reading through librayvec_oiio.so (oiio_module_abi.h): every format OpenImageIO knows, for the
// files that are neither PNG nor EXR. The module is $RAYVEC_OIIO_MODULE when that is set (a path),
// else the one beside the running executable, else the one in the build directory of the binary.
#pragma once
#include <string>

#include "image/image.h"

namespace rayvec {

// The file name of the module.
inline constexpr const char* kOiioModuleName = "librayvec_oiio.so";

// Reads `path` through the module, checking the declared size (image_budget.h) before the pixels.
// `encoded` is set for integer pixel formats (sRGB-encoded). Throws InputError naming the file when
// it is unreadable, RuntimeError naming the module when the module cannot be loaded.
Image read_with_oiio_module(const std::string& path, bool* encoded);

// True once the module has been loaded into this process (for the start-up guard test).
bool oiio_module_loaded();

}  // namespace rayvec
