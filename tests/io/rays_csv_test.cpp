// RAYS.csv reading: both widths, skipped lines, CRLF, and every error with its line number.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/input_error.h"
#include "io/rays_csv.h"
#include "test_support.h"

namespace rayvec {
namespace {

// The message of the InputError parse_rays_csv throws on `text` ("" when it does not throw).
std::string error_of(const std::string& text) {
  try {
    parse_rays_csv(text, "rays.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RaysCsv, ReadsSixAndEightFieldLines) {
  const RayBatch rays = parse_rays_csv("1,2,3,4,5,6\n-1.5e-3,0,0,0,0,-1,0.25,7.5\n", "r.csv");
  ASSERT_EQ(rays.size(), 2u);
  EXPECT_EQ(rays[0].org.x, 1.0f);
  EXPECT_EQ(rays[0].dir.z, 6.0f);
  EXPECT_EQ(rays[0].tmin, 0.0f);
  EXPECT_TRUE(std::isinf(rays[0].tmax));
  EXPECT_EQ(rays[1].org.x, -1.5e-3f);
  EXPECT_EQ(rays[1].tmin, 0.25f);
  EXPECT_EQ(rays[1].tmax, 7.5f);
}

TEST(RaysCsv, SkipsCommentsBlankLinesHeaderAndCrlf) {
  const std::string text =
      "# rays\r\nox,oy,oz,dx,dy,dz\r\n\r\n  \t\n 1, 2 ,3,0,0,1\r\n   # indented comment\n"
      "+4,5,6,0,1,0,0,inf";  // no final newline, leading '+', tmax = inf
  const RayBatch rays = parse_rays_csv(text, "r.csv");
  ASSERT_EQ(rays.size(), 2u);
  EXPECT_EQ(rays[0].org.y, 2.0f);
  EXPECT_EQ(rays[1].org.x, 4.0f);
  EXPECT_TRUE(std::isinf(rays[1].tmax));
}

TEST(RaysCsv, ReadsBackShortestFloatText) {
  // Every float printed shortest (or %.9g) must read back to the same bits.
  const float values[] = {0.1f, 1.0f / 3.0f, 3.4028235e38f, 1.17549435e-38f, 1e-45f, -7.006492e-44f};
  for (float x : values) {
    char buf[64];
    // Read as tmin: origins are bounded by the coordinate range, tmin only by tmax.
    std::snprintf(buf, sizeof buf, "0,0,0,1,0,0,%.9g,inf\n", x);
    EXPECT_EQ(parse_rays_csv(buf, "r.csv")[0].tmin, x) << buf;
  }
}

TEST(RaysCsv, WrongFieldCountNamesLineAndCounts) {
  const std::string e = error_of("# c\n1,2,3,4,5,6\n1,2,3,4,5\n");
  EXPECT_NE(e.find("rays.csv:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("found 5 fields"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 6"), std::string::npos) << e;
  EXPECT_NE(error_of("1,2,3,4,5,6,7\n").find("rays.csv:1: found 7 fields"), std::string::npos);
}

TEST(RaysCsv, UnparsableFieldIsQuoted) {
  const std::string e = error_of("1,2,3,4,5,6\n\n1,2,x3,4,5,6\n");
  EXPECT_NE(e.find("rays.csv:3: field 3 'x3' is not a number"), std::string::npos) << e;
  EXPECT_NE(error_of("1,2,,4,5,6\n").find("rays.csv:1: field 3 '' is empty"), std::string::npos);
  EXPECT_NE(error_of("1,2,3 4,4,5,6\n").find("'3 4' is not a number"), std::string::npos);
  EXPECT_NE(error_of("1,2,1e39,4,5,6\n").find("'1e39' is out of range"), std::string::npos);
}

TEST(RaysCsv, NonFiniteOriginOrDirectionIsRejected) {
  EXPECT_NE(error_of("nan,0,0,1,0,0\n").find("rays.csv:1: origin must be finite, but ox is nan"),
            std::string::npos);
  EXPECT_NE(error_of("0,0,0,1,0,0\n0,0,0,1,-inf,0\n").find("rays.csv:2: direction must be finite"),
            std::string::npos);
}

TEST(RaysCsv, ZeroDirectionIsRejected) {
  EXPECT_NE(error_of("1,1,1,0,-0,0\n").find("rays.csv:1: direction is zero"), std::string::npos);
}

TEST(RaysCsv, BadIntervalIsRejected) {
  EXPECT_NE(error_of("0,0,0,1,0,0,2,1\n").find("rays.csv:1: tmin (2) is greater than tmax (1)"),
            std::string::npos);
  EXPECT_NE(error_of("0,0,0,1,0,0,nan,1\n").find("rays.csv:1: tmin is NaN"), std::string::npos);
  EXPECT_NE(error_of("0,0,0,1,0,0,0,nan\n").find("rays.csv:1: tmax is NaN"), std::string::npos);
  EXPECT_EQ(error_of("0,0,0,1,0,0,-1,inf\n"), "");
}

TEST(RaysCsv, MissingFileIsInputError) {
  const std::string path = test::temp_dir("rays_missing") + "/none.csv";
  try {
    read_rays_csv(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": cannot read"), std::string::npos) << e.what();
  }
}

TEST(RaysCsv, ReadsAFileOfManyRays) {
  std::string text;
  for (int i = 0; i < 20000; ++i)
    text += std::to_string(i) + ",0.5,-1e-3," + std::to_string(i % 7 + 1) + ",0,1\n";
  const std::string path = test::temp_dir("rays_many") + "/rays.csv";
  test::write_file(path, text);
  const RayBatch rays = read_rays_csv(path);
  ASSERT_EQ(rays.size(), 20000u);
  EXPECT_EQ(rays[19999].org.x, 19999.0f);
  EXPECT_EQ(rays[19999].dir.x, static_cast<float>(19999 % 7 + 1));
}

}  // namespace
}  // namespace rayvec
