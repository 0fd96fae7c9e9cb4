// EXR reading and writing through librayvec_exr.so (exr_module_abi.h), loaded on first use. The module
// is $RAYVEC_EXR_MODULE when that is set (a path), else the one beside the running executable, else
// the one in the build directory of the binary.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"

namespace rayvec {

// Reads the first part of a flat (not deep) EXR as float channels, linear as stored. The header is
// checked (exr_header.h, image_budget.h) before any pixel is decoded, and pixels are read a strip of
// scanlines at a time, so a file whose header promises more than it holds fails after a strip, not
// after allocating the whole raster. Channel order: each layer's R G B A Z first, then the rest
// alphabetically; unlayered channels before layered ones (R G B Z id N.x N.y N.z), as
// OpenImageIO orders them. Throws InputError naming the file, RuntimeError naming the module when it
// cannot be loaded.
Image read_exr(const std::string& path);

// Encodes every channel of `image` as 32-bit float, ZIP-compressed scanlines, with `metadata` as
// string attributes. Throws RuntimeError.
std::vector<std::uint8_t> encode_exr(const Image& image, const ImageMetadata& metadata);

// Loads the module now; throws RuntimeError naming it when it cannot be loaded. For commands that
// will write an EXR at the end of their work, so that a missing module fails before the work.
void require_exr_module();

}  // namespace rayvec
