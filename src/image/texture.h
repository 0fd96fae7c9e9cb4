// Texture: a map_Kd image as the renderer samples it, in linear RGB. A file of 8-bit values (PNG,
// JPEG, 8-bit TGA, …) keeps its sRGB codes, three bytes a texel, decoded on lookup by a 256-entry
// table (srgb8.h) into the very floats decoding at load gave, in a quarter of the memory; any other
// file (16-bit, float) keeps linear floats.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "image/image.h"
#include "math/vec3.h"

namespace rayvec {

class Texture {
 public:
  Texture() = default;
  // From a file's pixels as read_image gives them (`encoded`: an integer format, sRGB-encoded
  // values; else linear): the first three channels, or the first one thrice when there are fewer
  // (grey); alpha and the rest are dropped.
  Texture(const Image& raw, bool encoded);
  // From a file's 8-bit codes, kept as they are (16-bit values: as Texture(image_of_bytes(raw), true)).
  explicit Texture(const ImageBytes& raw);

  int width() const { return width_; }
  int height() const { return height_; }
  bool holds_codes() const { return !codes_.empty(); }  // 8-bit sRGB codes, not floats
  std::size_t bytes() const { return codes_.size() + linear_.size() * sizeof(float); }

  // The linear RGB of texel (x, y), 0 ≤ x < width, 0 ≤ y < height; row 0 is the top row.
  Vec3f texel(int x, int y) const {
    const std::size_t i = (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3;
    if (!codes_.empty()) return {decode_[codes_[i]], decode_[codes_[i + 1]], decode_[codes_[i + 2]]};
    return {linear_[i], linear_[i + 1], linear_[i + 2]};
  }

 private:
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> codes_;  // width · height · 3 sRGB codes, or empty
  std::vector<float> linear_;        // width · height · 3 linear floats, or empty
  const float* decode_ = nullptr;    // srgb8_decode_table()
};

}  // namespace rayvec
