// map_Kd textures: an OBJ quad with texture coordinates and an MTL map_Kd (with and without its
// scale and offset options), rendered through the CLI.
// A 2x1 linear EXR texture (left texel red, right texel green) on a quad lit head-on (headon_quad.h)
// reads back as the bilinearly filtered texel colour.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/image_io.h"
#include "headon_quad.h"
#include "test_support.h"

namespace rayvec {
namespace {

// The quad textured by a 2x1 linear EXR, left texel red and right texel green, through the MTL line
// `map_Kd OPTIONS tex.exr`; its texture coordinates run from u = 0 at the left edge to 1 at the right.
Image render_textured_quad(const std::string& dir, const std::string& options) {
  Image tex(2, 1, {"R", "G", "B"});
  tex.at(0, 0, 0) = 1.0f;
  tex.at(1, 0, 1) = 1.0f;
  write_image(dir + "/tex.exr", tex);
  return test::render_headon_quad(dir, "newmtl textured\nKd 1 1 1\nmap_Kd " + options + " tex.exr\nillum 1\n",
                                  "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl textured\nf 1/1 2/2 3/3 4/4\n");
}

// Expects each column on the quad to read the texture at u·scale + offset: bilinear lookup with
// repeat wrapping between the texel centres 0.25 (red) and 0.75 (green), so the red weight is 1 −
// (distance to the nearest red centre 0.25 + k) / 0.5.
void expect_texture_at(const Image& img, double scale, double offset) {
  const int checked = test::for_each_quad_column(img, [&](int px, double x) {
    const double u = (x + 1.0) / 2.0 * scale + offset;
    const double d = std::abs(u - 0.25 - std::round(u - 0.25));
    const double red = 1.0 - d / 0.5;
    test::expect_quad_colour(img, px, red, 1.0 - red, 0.0, "u " + std::to_string(u));
  });
  EXPECT_GE(checked, 10);
}

TEST(Texture, MapKdColoursTheSurfaceByTextureCoordinates) {
  const Image img = render_textured_quad(test::temp_dir("texture"), "");
  expect_texture_at(img, 1, 0);
  EXPECT_NEAR(img.at(2, test::kQuadRow, 0), 0.0f, 1e-6f) << "background outside the quad";
}

TEST(Texture, MapKdScaleAndOffsetPlaceTheTexture) {
  // twice across the quad, shifted by a quarter: `-s 2 1 1 -o 0.25 0 0`
  expect_texture_at(render_textured_quad(test::temp_dir("texture_placed"), "-s 2 1 1 -o 0.25 0 0"), 2, 0.25);
}

TEST(Texture, APlacementBeyondFloatRangeReadsTheTexturesCorner) {
  // u · 3e38 + 3e38 overflows float on most of the quad: such coordinates wrap to 0 (halfway
  // between the two texel centres, filtered), never NaN; where it stays finite it is a whole number
  // in float, which wraps to 0 too
  const Image img = render_textured_quad(test::temp_dir("texture_overflow"), "-s 3e38 1 1 -o 3e38 0 0");
  const int checked = test::for_each_quad_column(
      img, [&](int px, double) { test::expect_quad_colour(img, px, 0.5, 0.5, 0.0, "u at infinity"); });
  EXPECT_GE(checked, 10);
}

}  // namespace
}  // namespace rayvec
