#include "image/texture.h"

#include <algorithm>
#include <bit>
#include <cstddef>

#include "image/image_io.h"
#include "image/srgb8.h"

namespace rayvec {
namespace {

// The 8-bit code k whose value the readers make, k · (1/255) in float, is `v` bit for bit; or −1.
int code_of(float v) {
  const float scaled = v * 255.0f;
  if (!(scaled >= 0.0f && scaled <= 255.0f)) return -1;
  const int k = int(scaled + 0.5f);
  return std::bit_cast<std::uint32_t>(float(k) * (1.0f / 255.0f)) == std::bit_cast<std::uint32_t>(v) ? k : -1;
}

}  // namespace

Texture::Texture(const Image& raw, bool encoded) : width_(raw.width), height_(raw.height) {
  const std::size_t count = std::size_t(raw.width) * std::size_t(raw.height);
  const std::size_t n = std::size_t(raw.nchannels());
  const std::size_t channel[3] = {0, n >= 3 ? 1u : 0u, n >= 3 ? 2u : 0u};
  if (encoded) {
    codes_.resize(count * 3);
    bool all_codes = true;
    for (std::size_t p = 0; p < count && all_codes; ++p)
      for (std::size_t c = 0; c < 3; ++c) {
        const int k = code_of(raw.pixels[p * n + channel[c]]);
        all_codes = all_codes && k >= 0;
        codes_[p * 3 + c] = std::uint8_t(k);
      }
    if (all_codes) {
      decode_ = srgb8_decode_table();
      return;
    }
    codes_ = {};
  }
  linear_.resize(count * 3);
  for (std::size_t p = 0; p < count; ++p)
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = raw.pixels[p * n + channel[c]];
      linear_[p * 3 + c] = encoded ? srgb_decode(v) : v;
    }
}

Texture::Texture(const ImageBytes& raw) {
  if (raw.bits != 8) {
    *this = Texture(image_of_bytes(raw), true);
    return;
  }
  width_ = raw.width;
  height_ = raw.height;
  const std::size_t count = std::size_t(raw.width) * std::size_t(raw.height);
  const std::size_t n = std::size_t(raw.channels);
  const std::size_t channel[3] = {0, n >= 3 ? 1u : 0u, n >= 3 ? 2u : 0u};
  codes_.resize(count * 3);
  if (n == 3) {
    std::copy(raw.bytes.begin(), raw.bytes.begin() + std::ptrdiff_t(count * 3), codes_.begin());
  } else {
    for (std::size_t p = 0; p < count; ++p)
      for (std::size_t c = 0; c < 3; ++c) codes_[p * 3 + c] = raw.bytes[p * n + channel[c]];
  }
  decode_ = srgb8_decode_table();
}

}  // namespace rayvec
