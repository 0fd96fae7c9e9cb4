// Image: a float raster with named channels, the form every image file is read into and written from.
// Pixels are interleaved (R G B [Z N.x ...]) and row 0 is the top row, as in EXR and PNG.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "platform/large_buffer.h"

namespace rayvec {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;                 // e.g. {"R", "G", "B"}; the first three are colour
  std::vector<float, LargeAllocator<float>> pixels;  // width * height * channels.size()

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

// Integer pixels as a PNG or JPEG stores them (sRGB-encoded values), interleaved, row 0 at the top:
// 8-bit codes, or 16-bit values in host order. What a texture keeps (texture.h) without a float
// image in between.
struct ImageBytes {
  int width = 0;
  int height = 0;
  int channels = 0;                 // 1 (Y), 2 (Y A), 3 (R G B) or 4 (R G B A)
  int bits = 8;                     // 8 or 16
  std::vector<std::uint8_t> bytes;  // width · height · channels · bits / 8

  std::size_t values() const { return std::size_t(width) * std::size_t(height) * std::size_t(channels); }
};

// The float image of `raw`, values as stored (8-bit v·(1/255), 16-bit v·(1/65535), still
// sRGB-encoded), its channels named by their count: Y, Y A, R G B or R G B A.
Image image_of_bytes(const ImageBytes& raw);

}  // namespace rayvec
