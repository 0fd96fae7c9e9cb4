// verts.csv / meshes.csv reading (the CUDA study's format): nan rows kept, indices validated.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/input_error.h"
#include "io/visibility_csv.h"

namespace rayvec {
namespace {

std::string faces_error(const std::string& text, std::size_t vertex_count) {
  try {
    parse_faces_csv(text, "meshes.csv", vertex_count);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string verts_error(const std::string& text) {
  try {
    parse_verts_csv(text, "verts.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(VisibilityCsv, ReadsScientificNotationAndKeepsNanRows) {
  const auto v = parse_verts_csv(
      "-6.195182353258132935e-02,-5.577753782272338867e-01,5.792263150215148926e-01\n"
      "nan,nan,nan\r\n"
      "1, 2, 3\n",
      "verts.csv");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].x, -6.195182353258132935e-02f);
  EXPECT_EQ(v[0].z, 5.792263150215148926e-01f);
  EXPECT_TRUE(std::isnan(v[1].x));
  EXPECT_EQ(v[2].y, 2.0f);
}

TEST(VisibilityCsv, ReadsIndicesWrittenAsFloats) {
  const auto f = parse_faces_csv(
      "1.000000000000000000e+00,2.000000000000000000e+00,0.000000000000000000e+00\n", "m.csv", 3);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0], (std::array<uint32_t, 3>{1, 2, 0}));
}

TEST(VisibilityCsv, BadIndicesNameFileAndLine) {
  EXPECT_NE(faces_error("0,1,2\n0,1.5,2\n", 3).find("meshes.csv:2: field 2 (1.5) is not an integer"),
            std::string::npos);
  EXPECT_NE(faces_error("0,1,-1\n", 3).find("meshes.csv:1: field 3 (-1) is a negative"), std::string::npos);
  EXPECT_NE(faces_error("\n0,1,3\n", 3)
                .find("meshes.csv:2: field 3 (3) is out of range: the vertex file has 3 rows"),
            std::string::npos);
  EXPECT_NE(faces_error("nan,1,2\n", 3).find("meshes.csv:1: field 1 (nan) is not an integer"),
            std::string::npos);
  EXPECT_NE(faces_error("0,1\n", 3).find("meshes.csv:1: found 2 fields, expected 3"), std::string::npos);
  EXPECT_NE(faces_error("0,1,two\n", 3).find("meshes.csv:1: field 3 'two' is not a number"),
            std::string::npos);
}

TEST(VisibilityCsv, BadVertexRowsNameFileAndLine) {
  EXPECT_NE(verts_error("0,0,0\n1,2\n").find("verts.csv:2: found 2 fields, expected 3"), std::string::npos);
  EXPECT_NE(verts_error("0,0,zero\n").find("verts.csv:1: field 3 'zero' is not a number"), std::string::npos);
}

}  // namespace
}  // namespace rayvec
