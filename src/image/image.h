// Image: a float raster with named channels, the form every image file is read into and written from.
// Pixels are interleaved (R G B [Z N.x ...]) and row 0 is the top row, as in EXR and PNG.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace rayvec {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;  // e.g. {"R", "G", "B"}; the first three are colour
  std::vector<float> pixels;          // width * height * channels.size()

  Image() = default;
  Image(int w, int h, std::vector<std::string> names)
      : width(w),
        height(h),
        channels(std::move(names)),
        pixels(std::size_t(w) * std::size_t(h) * channels.size(), 0.0f) {}

  int nchannels() const { return static_cast<int>(channels.size()); }
  float& at(int x, int y, int c) {
    return pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * channels.size() + c];
  }
  float at(int x, int y, int c) const {
    return pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * channels.size() + c];
  }
};

}  // namespace rayvec
