#include "image/srgb8.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "image/png_encoder.h"
#include "test_support.h"

namespace rayvec {
namespace {

// The table lookup gives the pow() reference's byte: on a sweep of every 64th float in [0, 1]
// (16.6 million values), and around every place where the byte changes.
TEST(Srgb8, EqualsThePowReferenceOnASweepOfFloats) {
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  std::uint64_t differ = 0;
  for (std::uint32_t bits = 0; bits <= one; bits += 64) {
    const float v = std::bit_cast<float>(bits);
    differ += srgb8(v) != srgb8_reference(v);
  }
  EXPECT_EQ(differ, 0u);
}

TEST(Srgb8, EqualsThePowReferenceAroundEveryStep) {
  for (int k = 1; k <= 255; ++k) {
    // where the byte becomes k, from the inverse formula, then exactly by walking up a few ulps
    const float guess = srgb_decode((float(k) - 0.5f) / 255.0f);
    float v = guess * (1 - 1e-5f);
    ASSERT_LT(srgb8_reference(v), k) << "the walk must start below byte " << k;
    while (srgb8_reference(v) < k) v = std::nextafter(v, 2.0f);
    float around = v;
    for (int i = 0; i < 4; ++i) around = std::nextafter(around, 0.0f);
    for (int i = 0; i < 8; ++i, around = std::nextafter(around, 2.0f))
      ASSERT_EQ(srgb8(around), srgb8_reference(around)) << "byte " << k << " at " << around;
  }
}

TEST(Srgb8, SpecialValues) {
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(srgb8(-inf), 0);
  EXPECT_EQ(srgb8(-1.0f), 0);
  EXPECT_EQ(srgb8(-0.0f), 0);
  EXPECT_EQ(srgb8(std::numeric_limits<float>::denorm_min()), 0);
  EXPECT_EQ(srgb8(0.5f), srgb8_reference(0.5f));
  EXPECT_EQ(srgb8(1.0f), 255);
  EXPECT_EQ(srgb8(7.0f), 255);
  EXPECT_EQ(srgb8(inf), 255);
}

// The row form gives srgb8 of each channel, a missing channel as 0, for every channel count.
TEST(Srgb8, PixelsGiveTheBytesOfEachChannel) {
  const float inf = std::numeric_limits<float>::infinity();
  const float values[] = {std::numeric_limits<float>::quiet_NaN(),
                          -inf,
                          -0.0f,
                          0.0f,
                          1e-30f,
                          1.0f / 8192.0f,
                          1.6e-4f,
                          0.0031308f,
                          0.2f,
                          0.5f,
                          0.9955f,
                          0.99999994f,
                          1.0f,
                          3.0f,
                          inf};
  constexpr std::size_t kCount = sizeof values / sizeof values[0];
  for (int channels = 1; channels <= 5; ++channels) {
    std::vector<float> linear(kCount * std::size_t(channels));
    for (std::size_t i = 0; i < linear.size(); ++i) linear[i] = values[(i * 7) % kCount];
    std::vector<std::uint8_t> rgb(kCount * 3, 77);
    srgb8_pixels(linear.data(), channels, kCount, rgb.data());
    for (std::size_t p = 0; p < kCount; ++p)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(rgb[p * 3 + c], srgb8(c < channels ? linear[p * channels + c] : 0.0f))
            << channels << " channels, pixel " << p << ", channel " << c;
  }
}

// A texture's texels are the formula's floats bit for bit: 8-bit codes kept as codes and decoded by
// the table, values that are not codes (16-bit, out of range, −0) kept as floats, grey widened; and a
// PNG of all codes read as a texture.
TEST(Srgb8, TextureDecodeEqualsTheFormula) {
  std::vector<float> codes;
  for (int k = 0; k < 256; ++k) codes.push_back(float(k) * (1.0f / 255.0f));
  std::vector<float> with_minus_zero = codes, with_others = codes;
  with_minus_zero.push_back(-0.0f);  // not code 0: the formula keeps its sign
  for (const float v : {0.5f, 1000.0f / 65535.0f, 1e-6f, 1.5f, -0.25f, 2.0f / 255.0f + 1e-7f})
    with_others.push_back(v);
  const std::vector<std::string> names[] = {{"Y"}, {}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  // the codes alone are kept as codes; with any other value, as floats
  for (const std::vector<float>* values : {&codes, &with_minus_zero, &with_others})
    for (const int channels : {1, 3, 4}) {
      const std::size_t count = values->size();
      Image in(int(count), 1, names[channels - 1]);
      for (std::size_t i = 0; i < in.pixels.size(); ++i) in.pixels[i] = (*values)[(i * 5) % count];
      const Texture tex(in, true);
      EXPECT_EQ(tex.holds_codes(), values == &codes);
      for (std::size_t p = 0; p < count; ++p)
        for (int c = 0; c < 3; ++c) {
          const float v = in.pixels[p * std::size_t(channels) + (channels >= 3 ? std::size_t(c) : 0)];
          const Vec3f t = tex.texel(int(p), 0);
          ASSERT_EQ(std::bit_cast<std::uint32_t>(c == 0   ? t.x
                                                 : c == 1 ? t.y
                                                          : t.z),
                    std::bit_cast<std::uint32_t>(srgb_decode(v)))
              << channels << " channels, value " << v;
        }
    }
  std::vector<std::uint8_t> rgb(256 * 3);
  for (int k = 0; k < 256; ++k)
    rgb[std::size_t(k) * 3] = rgb[std::size_t(k) * 3 + 1] = rgb[std::size_t(k) * 3 + 2] = std::uint8_t(k);
  const std::string path = test::temp_dir("srgb8_texture") + "/codes.png";
  const std::vector<std::uint8_t> png =
      encode_png_rgb8(256, 1, [&](int, std::uint8_t* row) { std::copy(rgb.begin(), rgb.end(), row); }, {});
  test::write_file(path, std::string(png.begin(), png.end()));
  const Texture tex = read_texture(path);
  EXPECT_TRUE(tex.holds_codes());
  for (int k = 0; k < 256; ++k) EXPECT_EQ(tex.texel(k, 0).y, srgb_decode(float(k) * (1.0f / 255.0f))) << k;
}

}  // namespace
}  // namespace rayvec
