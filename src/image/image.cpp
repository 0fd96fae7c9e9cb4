#include "image/image.h"

#include <cstring>

namespace rayvec {
namespace {

std::vector<std::string> channel_names(int channels) {
  switch (channels) {
    case 1: return {"Y"};
    case 2: return {"Y", "A"};
    case 3: return {"R", "G", "B"};
    default: return {"R", "G", "B", "A"};
  }
}

}  // namespace

Image image_of_bytes(const ImageBytes& raw) {
  Image image(raw.width, raw.height, channel_names(raw.channels));
  const std::size_t n = raw.values();
  if (raw.bits == 16) {
    for (std::size_t i = 0; i < n; ++i) {
      std::uint16_t v;
      std::memcpy(&v, raw.bytes.data() + 2 * i, 2);
      image.pixels[i] = float(v) * (1.0f / 65535.0f);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) image.pixels[i] = float(raw.bytes[i]) * (1.0f / 255.0f);
  }
  return image;
}

}  // namespace rayvec
