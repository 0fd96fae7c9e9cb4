#include "image/crafted_images.h"

#include <cstring>
#include <stdexcept>

namespace rayvec::test {
namespace {

std::string be32(std::uint32_t v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }

std::string chunk(const std::string& type, const std::string& data) {
  return be32(std::uint32_t(data.size())) + type + data + be32(png_crc32(type + data));
}

}  // namespace

std::uint32_t png_crc32(const std::string& bytes) {  // bit by bit
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

std::string png_claiming(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr = be32(width) + be32(height) + std::string("\x08\x02\x00\x00\x00", 5);
  // A zlib stream that starts a stored block and then ends: the pixels are missing.
  const std::string idat("\x78\x01\x00\x10\x00\xef\xff\x00\x00\x00\x00\x00\x00\x00\x00\x00", 16);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) + chunk("IEND", "");
}

std::string exr_claiming(std::string exr, std::int32_t width, std::int32_t height) {
  const std::string key("dataWindow\0box2i\0", 17);
  const auto at = exr.find(key);
  if (at == std::string::npos) throw std::runtime_error("no dataWindow attribute");
  const std::int32_t box[4] = {0, 0, width - 1, height - 1};  // little-endian, as EXR stores it
  std::memcpy(exr.data() + at + key.size() + 4, box, sizeof box);
  return exr;
}

}  // namespace rayvec::test
