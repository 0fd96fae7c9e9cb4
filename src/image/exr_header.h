// The header of an OpenEXR file, read through OpenEXRCore (exr_header.cpp is its only includer):
// the core library parses the header alone and allocates nothing for the pixels, so a size can be
// judged before the C++ library (exr_file.cpp) builds its tables for it.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace rayvec {

struct ExrHeader {
  int min_x = 0, min_y = 0;  // data window origin
  int width = 0, height = 0;
  std::vector<std::string> channels;  // as stored (alphabetical)
  bool subsampled = false;            // a channel with x/y sampling other than 1
  bool deep = false;
  int parts = 0;
};

// True when `bytes` start with the OpenEXR magic number.
bool has_exr_magic(const unsigned char* bytes, std::size_t size);

// Parses the header of the first part; throws InputError naming the file when it is not valid.
ExrHeader read_exr_header(const std::string& path);

}  // namespace rayvec
