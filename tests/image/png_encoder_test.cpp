// The PNG encoder: bands of rows deflated on their own join into one zlib stream that libpng reads
// back to the same rows, whatever the thread count; the chunks are whole, their CRCs right, the
// metadata kept. libpng checks the stream's Adler-32 (ACorruptChecksumIsCaught…), so a round trip
// of several bands also checks how the bands' sums were combined.
#include "image/png_encoder.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "image/crafted_images.h"
#include "image/png_file.h"
#include "io/input_error.h"
#include "test_support.h"

namespace rayvec {
namespace {

// Rows of RGB bytes: noise, or flat runs and gradients (what renders hold), from a seed.
std::vector<std::uint8_t> pixels(int width, int height, bool noise, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb[i] = noise ? std::uint8_t(rng())
                   : std::uint8_t((i / 3 % std::size_t(width)) / 7 + (i % 3) * 40 + rng() % 2);
  return rgb;
}

std::vector<std::uint8_t> encode(int width, int height, const std::vector<std::uint8_t>& rgb,
                                 const ImageMetadata& metadata = {}) {
  const std::size_t row = std::size_t(width) * 3;
  return encode_png_rgb8(
      width, height,
      [&](int y, std::uint8_t* out) { std::copy_n(rgb.data() + std::size_t(y) * row, row, out); }, metadata);
}

ImageBytes decode(const std::vector<std::uint8_t>& png) {
  const std::string path = test::temp_dir("png_encoder") + "/image.png";
  test::write_file(path, std::string(png.begin(), png.end()));
  return read_png_bytes(path);
}

struct Chunk {
  std::string type, data;
  std::size_t at;  // where its length field starts
  bool crc_ok;
};

std::uint32_t be32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

std::vector<Chunk> chunks(const std::vector<std::uint8_t>& png) {
  std::vector<Chunk> list;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t n = be32(&png[at]);
    Chunk c{std::string(png.begin() + long(at) + 4, png.begin() + long(at) + 8),
            std::string(png.begin() + long(at) + 8, png.begin() + long(at + 8 + n)), at, false};
    c.crc_ok = test::png_crc32(c.type + c.data) == be32(&png[at + 8 + n]);
    list.push_back(c);
    at += 12 + n;
  }
  return list;
}

TEST(PngEncoder, BandsJoinIntoOneStreamThatDecodesToTheRows) {
  // a single band, several of 291 rows (300 wide), and bands of one row (a row over 256 KiB)
  ASSERT_LT(png_band_rows(300), 1000);
  ASSERT_EQ(png_band_rows(90000), 1);
  const int sizes[][2] = {{1, 1}, {5, 3}, {300, 1000}, {90000, 3}};
  for (const auto& size : sizes)
    for (const bool noise : {false, true}) {
      const int width = size[0], height = size[1];
      const std::vector<std::uint8_t> rgb = pixels(width, height, noise, std::uint32_t(width + height));
      const ImageBytes back = decode(encode(width, height, rgb));
      ASSERT_EQ(back.width, width);
      ASSERT_EQ(back.height, height);
      ASSERT_EQ(back.channels, 3);
      ASSERT_EQ(back.bits, 8);
      EXPECT_TRUE(back.bytes == rgb) << width << "x" << height << (noise ? " noise" : " smooth");
    }
}

TEST(PngEncoder, BytesDoNotDependOnTheThreadCount) {
  const std::vector<std::uint8_t> rgb = pixels(300, 1000, false, 7);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::vector<std::uint8_t> one = encode(300, 1000, rgb);
  omp_set_num_threads(3);
  const std::vector<std::uint8_t> three = encode(300, 1000, rgb);
  omp_set_num_threads(threads);
  EXPECT_TRUE(one == three);
}

TEST(PngEncoder, ChunksAreWholeWithTheirCrcsAndTheMetadataKept) {
  // 1.5 MB of noise: a stream longer than one IDAT chunk holds
  const std::vector<std::uint8_t> png = encode(
      1024, 512, pixels(1024, 512, true, 3),
      {{"Software", "rayvec"}, {"rayvec:scene", "a b.json"}, {"cut", std::string("before\0after", 12)}});
  const std::vector<Chunk> list = chunks(png);
  ASSERT_GE(list.size(), 9u);
  EXPECT_EQ(std::string(png.begin(), png.begin() + 8), std::string("\x89PNG\r\n\x1a\n", 8));
  std::vector<std::string> types;
  for (const Chunk& c : list) {
    EXPECT_TRUE(c.crc_ok) << c.type;
    if (types.empty() || types.back() != c.type) types.push_back(c.type);
  }
  const std::vector<std::string> order{"IHDR", "gAMA", "sRGB", "cHRM", "tEXt", "IDAT", "IEND"};
  EXPECT_EQ(types, order);  // the IDAT chunks one after the other
  EXPECT_EQ(list.back().at + 12, png.size());
  std::vector<std::string> texts;
  std::size_t idat = 0;
  for (const Chunk& c : list) {
    if (c.type == "tEXt") texts.push_back(c.data);
    if (c.type == "IDAT") {
      EXPECT_LE(c.data.size(), std::size_t(1) << 20);
      ++idat;
    }
  }
  EXPECT_GE(idat, 2u);
  const std::vector<std::string> expected{std::string("Software\0rayvec", 15),
                                          std::string("rayvec:scene\0a b.json", 21),
                                          std::string("cut\0before", 10)};
  EXPECT_EQ(texts, expected);
}

TEST(PngEncoder, ACorruptChecksumIsCaughtByTheReader) {
  const int width = 300, height = 1000;
  std::vector<std::uint8_t> png = encode(width, height, pixels(width, height, false, 11));
  const std::vector<Chunk> list = chunks(png);
  const auto last_idat =
      std::find_if(list.rbegin(), list.rend(), [](const Chunk& c) { return c.type == "IDAT"; });
  ASSERT_NE(last_idat, list.rend());
  // the stream's last byte, Adler-32's lowest; then the chunk's CRC made right again
  const std::size_t data = last_idat->at + 8, n = last_idat->data.size();
  png[data + n - 1] ^= 0x01;
  const std::uint32_t crc =
      test::png_crc32("IDAT" + std::string(png.begin() + long(data), png.begin() + long(data + n)));
  for (int k = 0; k < 4; ++k) png[data + n + std::size_t(k)] = std::uint8_t(crc >> (24 - 8 * k));
  EXPECT_THROW(decode(png), InputError);
}

TEST(PngEncoder, AKeyThatIsNoPngKeywordOrAnEmptyImageIsARuntimeError) {
  const std::vector<std::uint8_t> rgb = pixels(2, 2, false, 1);
  for (const std::string& key : {std::string(), std::string(" lead"), std::string("trail "),
                                 std::string("a  b"), std::string(80, 'k'), std::string("tab\there")})
    EXPECT_THROW(encode(2, 2, rgb, {{key, "text"}}), RuntimeError) << "'" << key << "'";
  EXPECT_NO_THROW(encode(2, 2, rgb, {{"rayvec:render seconds", "1"}, {std::string(79, 'k'), ""}}));
  EXPECT_THROW(encode(0, 2, rgb), RuntimeError);
  EXPECT_THROW(encode(2, 0, rgb), RuntimeError);
}

}  // namespace
}  // namespace rayvec
