// `rayvec compare` as a golden-image test tool: one comparison space for EXR against PNG, the
// idiff-style percentage and warn criteria with their exit statuses, difference images, and errors
// that name both files and their sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/compare.h"
#include "image/image_io.h"
#include "test_support.h"

namespace rayvec {
namespace {

using test::run_cli;

Image ramp(int w, int h) {
  Image img(w, h, {"R", "G", "B"});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.at(x, y, 0) = float(x) / float(w - 1);
      img.at(x, y, 1) = 0.04f * float(y);
      img.at(x, y, 2) = 0.5f;
    }
  return img;
}

std::string q(const std::string& path) { return "'" + path + "'"; }

TEST(CompareCli, ExrAndPngOfOneImageCompareInOneSpace) {
  const std::string dir = test::temp_dir("cmp_space");
  write_image(dir + "/a.exr", ramp(10, 10));
  write_image(dir + "/a.png", ramp(10, 10));
  const auto r = run_cli("compare " + q(dir + "/a.exr") + " " + q(dir + "/a.png") + " --max-pixel 0.0025");
  EXPECT_EQ(r.status, 0) << r.out << r.err;  // only the 8-bit rounding (<= 0.5/255) remains
  EXPECT_NE(r.out.find("space: sRGB-encoded in [0,1]; " + dir + "/a.exr converted from linear"),
            std::string::npos)
      << r.out;
  const auto same_kind = run_cli("compare " + q(dir + "/a.png") + " " + q(dir + "/a.png"));
  EXPECT_NE(same_kind.out.find("space: as stored (both sRGB-encoded in [0,1])"), std::string::npos)
      << same_kind.out;
}

TEST(CompareCli, FailPercentAllowsAShareOfPixelsOverTheThreshold) {
  const std::string dir = test::temp_dir("cmp_percent");
  Image a = ramp(10, 10), b = a;
  b.at(3, 3, 0) += 0.5f;  // 2 of 100 pixels differ
  b.at(7, 1, 2) += 0.3f;
  write_image(dir + "/a.exr", a);
  write_image(dir + "/b.exr", b);
  const std::string base = "compare " + q(dir + "/a.exr") + " " + q(dir + "/b.exr") + " --threshold 0.1";
  EXPECT_EQ(run_cli(base + " --fail-percent 2").status, 0);
  const auto fail = run_cli(base + " --fail-percent 1.5");
  EXPECT_EQ(fail.status, 1) << fail.out;
  EXPECT_NE(fail.out.find("FAIL: percent of pixels over the threshold 2 > --fail-percent 1.5"),
            std::string::npos)
      << fail.out;
  EXPECT_EQ(run_cli(base + " --fail-percent 100").status, 0);
  for (const char* option : {"--fail-percent", "--warn-percent"}) {
    const auto over = run_cli(base + " " + option + " 200");
    EXPECT_EQ(over.status, 2) << option;
    EXPECT_NE(over.err.find(std::string(option) + ": 200 is more than 100 percent of the pixels"),
              std::string::npos)
        << over.err;
  }
}

TEST(CompareCli, WarnLimitsExitThreeAndFailLimitsWin) {
  const std::string dir = test::temp_dir("cmp_warn");
  Image a = ramp(10, 10), b = a;
  b.at(3, 3, 0) += 0.2f;
  write_image(dir + "/a.exr", a);
  write_image(dir + "/b.exr", b);
  const std::string base = "compare " + q(dir + "/a.exr") + " " + q(dir + "/b.exr");
  const auto warn = run_cli(base + " --max-pixel 0.5 --warn-pixel 0.1");
  EXPECT_EQ(warn.status, 3) << warn.out;
  EXPECT_NE(warn.out.find("WARN: max pixel error"), std::string::npos) << warn.out;
  EXPECT_NE(warn.out.find("\nwarn\n"), std::string::npos) << warn.out;
  EXPECT_EQ(run_cli(base + " --threshold 0.1 --warn-percent 0.5").status, 3);
  EXPECT_EQ(run_cli(base + " --threshold 0.1 --warn-percent 1").status, 0);
  EXPECT_EQ(run_cli(base + " --warn-rmse 0.0001").status, 3);
  EXPECT_EQ(run_cli(base + " --max-pixel 0.1 --warn-pixel 0.1").status, 1);
}

TEST(CompareCli, DiffWritesAbsoluteScaledAndFalseColourImages) {
  const std::string dir = test::temp_dir("cmp_diff");
  Image a = ramp(8, 4), b = a;
  b.at(2, 1, 1) += 0.25f;
  b.at(5, 2, 0) -= 0.125f;
  write_image(dir + "/a.exr", a);
  write_image(dir + "/b.exr", b);
  const std::string base =
      "compare " + q(dir + "/a.exr") + " " + q(dir + "/b.exr") + " --threshold 0.2 --diff ";
  ASSERT_EQ(run_cli(base + q(dir + "/abs.exr")).status, 0);
  const Image abs = read_image(dir + "/abs.exr");
  EXPECT_FLOAT_EQ(abs.at(2, 1, 1), 0.25f);
  EXPECT_FLOAT_EQ(abs.at(5, 2, 0), 0.125f);
  EXPECT_FLOAT_EQ(abs.at(0, 0, 0), 0.0f);
  ASSERT_EQ(run_cli(base + q(dir + "/scaled.exr") + " --diff-mode scaled").status, 0);
  const Image scaled = read_image(dir + "/scaled.exr");
  EXPECT_FLOAT_EQ(scaled.at(2, 1, 1), 1.0f);
  EXPECT_FLOAT_EQ(scaled.at(5, 2, 0), 0.5f);
  const auto fc = run_cli(base + q(dir + "/fc.png") + " --diff-mode falsecolor");
  ASSERT_EQ(fc.status, 0) << fc.err;
  EXPECT_NE(fc.out.find("difference image: " + dir + "/fc.png (falsecolor)"), std::string::npos) << fc.out;
  const Image colours = read_image(dir + "/fc.png");
  EXPECT_FLOAT_EQ(colours.at(0, 0, 0) + colours.at(0, 0, 1) + colours.at(0, 0, 2), 0.0f);  // equal: black
  EXPECT_GT(colours.at(2, 1, 0), 0.9f);  // 0.25 > threshold 0.2: between yellow and red
  EXPECT_LT(colours.at(5, 2, 0), 0.1f);  // 0.125 < threshold: blue to green, no red
  EXPECT_EQ(run_cli(base + q(dir + "/x.png") + " --diff-mode sideways").status, 2);
  EXPECT_EQ(run_cli(base + q(dir + "/x.bmp")).status, 2);
}

TEST(CompareCli, SizeMismatchNamesBothFilesAndSizes) {
  const std::string dir = test::temp_dir("cmp_size");
  write_image(dir + "/big.png", ramp(8, 6));
  write_image(dir + "/small.exr", ramp(4, 3));
  const auto r = run_cli("compare " + q(dir + "/big.png") + " " + q(dir + "/small.exr"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/big.png is 8x6 but " + dir + "/small.exr is 4x3"), std::string::npos) << r.err;
}

TEST(Compare, SrgbEncodingMatchesThePngWriter) {
  const std::string dir = test::temp_dir("cmp_encode");
  Image lin = ramp(16, 2);
  lin.at(1, 1, 0) = 3.0f;  // clamped like the PNG writer
  lin.at(2, 1, 0) = std::nanf("");
  write_image(dir + "/x.png", lin);
  const Image png = read_image(dir + "/x.png");
  const Image enc = to_srgb_encoded(lin);
  for (std::size_t i = 0; i < png.pixels.size(); ++i)
    EXPECT_NEAR(enc.pixels[i], png.pixels[i], 0.5f / 255.0f) << i;
}

}  // namespace
}  // namespace rayvec
