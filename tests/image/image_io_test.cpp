// image_io: round trips through EXR and PNG, atomic writes, bad extensions; `rayvec compare` exits.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "image/compare.h"
#include "image/image_io.h"
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

TEST(ImageIo, UnknownExtensionIsInputErrorAndWritesNothing) {
  const std::string dir = test::temp_dir("ext");
  EXPECT_THROW(write_image(dir + "/a.bmpx", gradient(4, 4)), InputError);
  EXPECT_THROW(read_image(dir + "/missing.png"), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(ImageIo, WriteIntoMissingDirectoryIsRuntimeError) {
  EXPECT_THROW(write_image("/nonexistent-dir-rayvec/a.png", gradient(4, 4)), RuntimeError);
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
