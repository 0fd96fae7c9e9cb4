// image_io: round trips through EXR and PNG, atomic writes, bad extensions; `rayvec compare` exits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "image/compare.h"
#include "image/image_io.h"
#include "image/srgb8.h"
#include "io/input_error.h"
#include "test_support.h"

namespace rayvec {
namespace {

Image gradient(int w, int h, float scale = 1.0f) {
  Image img(w, h, {"R", "G", "B", "Z"});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.at(x, y, 0) = scale * float(x) / float(w - 1);
      img.at(x, y, 1) = scale * float(y) / float(h - 1);
      img.at(x, y, 2) = 0.25f * scale;
      img.at(x, y, 3) = 10.0f + float(x);
    }
  return img;
}

TEST(ImageIo, ExrRoundTripIsExactWithChannelsAndMetadata) {
  const std::string dir = test::temp_dir("exr");
  const Image img = gradient(13, 7, 3.0f);  // values above 1 must survive in EXR
  write_image(dir + "/a.exr", img, {{"rayvec:scene", "x.json"}});
  const Image back = read_image(dir + "/a.exr");
  ASSERT_EQ(back.width, 13);
  ASSERT_EQ(back.height, 7);
  ASSERT_EQ(back.nchannels(), 4);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(back.at(5, 3, c), img.at(5, 3, c)) << c;
  // only the final file remains: no temporaries
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(ImageIo, PngIsSrgbEncoded8Bit) {
  const std::string dir = test::temp_dir("png");
  Image img(2, 1, {"R", "G", "B"});
  img.at(0, 0, 0) = 0.2158605f;  // sRGB-encoded 128/255
  img.at(1, 0, 1) = 2.0f;        // clamped to 1
  write_image(dir + "/a.png", img);
  const Image back = read_image(dir + "/a.png");
  ASSERT_EQ(back.nchannels(), 3);
  EXPECT_NEAR(back.at(0, 0, 0), 128.0f / 255.0f, 0.5f / 255.0f);
  EXPECT_FLOAT_EQ(back.at(1, 0, 1), 1.0f);
  EXPECT_FLOAT_EQ(back.at(1, 0, 0), 0.0f);
  EXPECT_NEAR(srgb_decode(srgb_encode(0.3f)), 0.3f, 1e-6f);
}

TEST(ImageIo, PngRowsComeFromTheirOwnRowsWhateverTheChannels) {
  const std::string dir = test::temp_dir("png_rows");
  const Image img = gradient(37, 23);  // R G B Z: four floats a pixel, three bytes in the PNG
  write_image(dir + "/g.png", img);
  const Image back = read_image(dir + "/g.png");
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 23);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(back.at(x, y, c), float(srgb8(img.at(x, y, c))) * (1.0f / 255.0f))
            << x << "," << y << "," << c;
}

TEST(Image, APixelArrayOfAHugePageOrMoreStartsOnOne) {
  // A render's framebuffer: its first touch takes huge-page faults (platform/large_buffer.h).
  const Image image(640, 480, {"R", "G", "B"});  // 3.5 MiB
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(image.pixels.data()) % (std::size_t(2) << 20), 0u);
  EXPECT_EQ(image.pixels.back(), 0.0f);
}

TEST(ImageIo, UnknownExtensionIsInputErrorAndWritesNothing) {
  const std::string dir = test::temp_dir("ext");
  EXPECT_THROW(write_image(dir + "/a.bmpx", gradient(4, 4)), InputError);
  EXPECT_THROW(read_image(dir + "/missing.png"), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(ImageIo, WriteIntoMissingDirectoryIsRuntimeError) {
  EXPECT_THROW(write_image("/nonexistent-dir-rayvec/a.png", gradient(4, 4)), RuntimeError);
}

TEST(ImageIo, ExrChannelsReadBackInOpenImageIoOrder) {
  const std::string dir = test::temp_dir("exr_order");
  Image img(3, 2, {"R", "G", "B", "Z", "N.x", "N.y", "N.z", "id", "object_id"});
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = float(i) * 0.5f;
  write_image(dir + "/aov.exr", img);
  const Image back = read_image(dir + "/aov.exr");
  const std::vector<std::string> order = {"R", "G", "B", "Z", "id", "object_id", "N.x", "N.y", "N.z"};
  ASSERT_EQ(back.channels, order);
  for (int c = 0; c < back.nchannels(); ++c) {
    const int src =
        int(std::find(img.channels.begin(), img.channels.end(), back.channels[c]) - img.channels.begin());
    EXPECT_EQ(back.at(2, 1, c), img.at(2, 1, src)) << back.channels[c];
  }
}

TEST(ImageIo, PngRoundTripIsBitExactFor8BitValues) {
  const std::string dir = test::temp_dir("png_exact");
  Image img(256, 1, {"R", "G", "B"});
  for (int x = 0; x < 256; ++x)
    for (int c = 0; c < 3; ++c) img.at(x, 0, c) = srgb_decode(float(x) / 255.0f);
  write_image(dir + "/ramp.png", img);
  const Image back = read_image(dir + "/ramp.png");
  for (int x = 0; x < 256; ++x) EXPECT_EQ(back.at(x, 0, 1), float(x) * (1.0f / 255.0f)) << x;
}

TEST(ImageIo, OtherFormatsAreReadThroughTheOpenImageIoModule) {
  const std::string dir = test::temp_dir("ppm");
  // A 2x1 binary PPM: an sRGB-encoded texture in a format only OpenImageIO reads.
  test::write_file(dir + "/tex.ppm", std::string("P6\n2 1\n255\n\xff\x00\x00\x00\x80\x00", 17));
  const Image raw = read_image(dir + "/tex.ppm");
  ASSERT_EQ(raw.width, 2);
  EXPECT_FLOAT_EQ(raw.at(0, 0, 0), 1.0f);
  EXPECT_FLOAT_EQ(raw.at(1, 0, 1), 128.0f / 255.0f);
  const Texture tex = read_texture(dir + "/tex.ppm");
  EXPECT_EQ(tex.texel(1, 0).y, srgb_decode(128.0f / 255.0f));
  EXPECT_TRUE(tex.holds_codes());
  test::write_file(dir + "/junk.img", "not an image at all");
  EXPECT_THROW(read_image(dir + "/junk.img"), InputError);
}

// Every way a texture is made — 8-bit codes straight from PNG and JPEG, 16-bit PNG values, another
// format through OpenImageIO, linear EXR floats — gives each texel as decoding the file's float
// image would: srgb_decode of the first three channels (or the grey one thrice), EXR as stored.
TEST(ImageIo, TexturesOfEveryFormatAreTheirImagesDecoded) {
  const std::string dir = test::temp_dir("texture_kinds");
  const std::string data = std::string(RAYVEC_TEST_DATA);
  write_image(dir + "/a.exr", gradient(5, 3, 2.0f));
  test::write_file(dir + "/tex.ppm", std::string("P6\n2 1\n255\n\xff\x00\x00\x00\x80\x00", 17));
  const std::string files[] = {data + "/fuzz_corpus/image/rgb8.png",
                               data + "/fuzz_corpus/image/rgba8.png",
                               data + "/fuzz_corpus/image/grey16.png",
                               data + "/fuzz_corpus/image/palette2_trns_interlaced.png",
                               data + "/images/jpeg/rgb420.jpg",
                               data + "/images/jpeg/grey.jpg",
                               data + "/images/jpeg/cmyk.jpg",
                               dir + "/tex.ppm",
                               dir + "/a.exr"};
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    bool encoded = false;
    const Image raw = read_image(path, &encoded);
    const Texture tex = read_texture(path);
    ASSERT_EQ(tex.width(), raw.width);
    ASSERT_EQ(tex.height(), raw.height);
    for (int y = 0; y < raw.height; ++y)
      for (int x = 0; x < raw.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const float v = raw.at(x, y, raw.nchannels() >= 3 ? c : 0);
          const Vec3f t = tex.texel(x, y);
          ASSERT_EQ(c == 0   ? t.x
                    : c == 1 ? t.y
                             : t.z,
                    encoded ? srgb_decode(v) : v)
              << x << "," << y << "," << c;
        }
  }
}

TEST(Compare, MeasuresRmseMaxAndCount) {
  Image a(4, 1, {"R", "G", "B"}), b = a;
  b.at(1, 0, 0) = 0.5f;  // one channel of one pixel differs by 0.5
  const ImageDifference d = compare_images(a, b, 0.1);
  EXPECT_NEAR(d.rmse, std::sqrt(0.25 / 12.0), 1e-9);
  EXPECT_DOUBLE_EQ(d.max_error, 0.5);
  EXPECT_EQ(d.over_threshold, 1);
  EXPECT_TRUE(std::isinf(compare_images(a, a, 0.1).psnr));
  Image c(3, 1, {"R", "G", "B"});
  EXPECT_THROW(compare_images(a, c, 0.1), InputError);
}

TEST(CompareCli, ExitStatusesZeroOneTwo) {
  const std::string dir = test::temp_dir("cmpcli");
  Image a = gradient(8, 8), b = a;
  b.at(2, 2, 0) += 0.2f;
  write_image(dir + "/a.exr", a);
  write_image(dir + "/b.exr", b);
  write_image(dir + "/small.exr", gradient(4, 4));
  const auto same = test::run_cli("compare " + dir + "/a.exr " + dir + "/a.exr --max-rmse 0");
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("psnr: inf"), std::string::npos) << same.out;
  const auto loose = test::run_cli("compare " + dir + "/a.exr " + dir + "/b.exr --max-pixel 0.3");
  EXPECT_EQ(loose.status, 0) << loose.out;
  const auto strict = test::run_cli("compare " + dir + "/a.exr " + dir + "/b.exr --max-pixel 0.1");
  EXPECT_EQ(strict.status, 1) << strict.out;
  EXPECT_NE(strict.out.find("pixels over 0.1: 1 "), std::string::npos) << strict.out;
  EXPECT_EQ(test::run_cli("compare " + dir + "/a.exr " + dir + "/b.exr --max-rmse 0.001").status, 1);
  EXPECT_EQ(test::run_cli("compare " + dir + "/a.exr " + dir + "/small.exr").status, 2);
  const auto missing = test::run_cli("compare " + dir + "/a.exr " + dir + "/nope.png");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("nope.png"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace rayvec
