// The C interface of librayvec_oiio.so, the module that reads image formats other than PNG and EXR
// through OpenImageIO. The module is loaded with dlopen only when such a file is read, so no command
// pays for OpenImageIO's ~260 shared libraries at start
// (docs/benchmarks.md#decision-image-io-without-openimageio). Plain C types only: the module and the binary
// share no C++ objects.
#pragma once
#include <cstddef>

extern "C" {

// Bumped whenever a signature below changes; the loader refuses a module of another version.
constexpr int kRayvecOiioAbi = 1;

struct RayvecOiioInfo {
  int width, height, channels;
  int encoded;  // 1 for 8- and 16-bit integer pixels (sRGB-encoded), 0 for float (linear)
};

using RayvecOiioAbiFn = int (*)();
// Opens `path` and reads its header; null with `error` filled on failure.
using RayvecOiioOpenFn = void* (*)(const char* path, RayvecOiioInfo* info, char* error,
                                   std::size_t error_size);
// The name of channel `c` (valid until close).
using RayvecOiioChannelFn = const char* (*)(void* handle, int c);
// Reads every pixel as float, interleaved, into `pixels` (width*height*channels floats); 0 on failure.
using RayvecOiioReadFn = int (*)(void* handle, float* pixels, char* error, std::size_t error_size);
using RayvecOiioCloseFn = void (*)(void* handle);
}
