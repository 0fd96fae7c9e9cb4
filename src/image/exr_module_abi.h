// The C interface of librayvec_exr.so, the module that reads and writes EXR through OpenEXR. The
// binary loads it with dlopen the first time an EXR is read or written, so commands that touch no EXR
// do not pay for OpenEXR's five shared libraries at start (docs/benchmarks.md#decision-exr-module).
// Plain C types only: no C++ object or exception crosses. A failure comes back as a status and a
// message; the caller turns it into its own InputError or RuntimeError.
#pragma once
#include <cstddef>

extern "C" {

// Bumped whenever the table below or a signature in it changes; the loader refuses another version.
constexpr int kRayvecExrAbi = 2;

// The zlib level of the EXR files rayvec writes (docs/benchmarks.md#decision-exr-zip-level).
constexpr int kRayvecExrZipLevel = 1;

enum RayvecExrStatus : int {
  kRayvecExrOk = 0,
  kRayvecExrBadInput = 1,  // the file is not a readable EXR
  kRayvecExrFailed = 2,    // the work failed (encoding, memory)
};

// The first part's header, as OpenEXRCore parsed it (nothing allocated for pixels yet).
struct RayvecExrInfo {
  int min_x, min_y;   // data window origin
  int width, height;  // 0 when the data window's side is empty or does not fit an int
  int channels;
  int deep;        // 1 for deep scanline or tiled storage
  int subsampled;  // 1 when a channel has x/y sampling other than 1
};

// Called by encode for more room: returns a buffer of at least `size` bytes holding the bytes given
// so far (like realloc), or null when it cannot.
using RayvecExrGrowFn = unsigned char* (*)(void* user, std::size_t size);

struct RayvecExrModule {
  int abi;  // kRayvecExrAbi of the module's build; first, so a module of another layout is refused

  // Checks `path`'s header through OpenEXRCore and fills `info`; *file receives the handle to read
  // through and close. Nothing is decoded and the C++ reader builds no tables here.
  int (*open)(const char* path, void** file, RayvecExrInfo* info, char* error, std::size_t error_size);
  // The name of channel `c` as stored (alphabetical); valid until close.
  const char* (*channel)(void* file, int c);
  // Decodes rows [y0, y1) of the data window of the `count` channels `names`, as floats interleaved
  // in that order, into `pixels`, which addresses row 0 of the data window and holds at least y1 rows
  // of width * count floats. Refuses (bad input) a file whose header the C++ reader parses to another
  // data window or channel list than open reported, or whose pixel chunks do not lie within the file.
  int (*read_rows)(void* file, const char* const* names, int count, float* pixels, int y0, int y1,
                   char* error, std::size_t error_size);
  void (*close)(void* file);

  // Encodes width x height pixels of the `count` channels `names` (floats interleaved) as 32-bit float,
  // ZIP-compressed scanlines (zlib level kRayvecExrZipLevel) with `meta_count` string attributes keys[i] =
  // values[i]. The bytes go to the buffer `grow(user, …)` returns; *size receives their number.
  int (*encode)(int width, int height, const char* const* names, int count, const float* pixels,
                const char* const* keys, const char* const* values, int meta_count, RayvecExrGrowFn grow,
                void* user, std::size_t* size, char* error, std::size_t error_size);

  // The threads that compress and decompress line blocks in files opened or encoded from here on
  // (OpenEXR's global thread pool; 1: none beside the caller's).
  void (*set_threads)(int threads);
};

// The one symbol the module exports: rayvec_exr_module.
using RayvecExrModuleFn = const RayvecExrModule* (*)();
}

namespace rayvec {
inline constexpr const char* kExrModuleName = "librayvec_exr.so";
}
