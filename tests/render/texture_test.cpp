// map_Kd textures: an OBJ quad with texture coordinates and an MTL map_Kd, rendered through the CLI.
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

TEST(Texture, MapKdColoursTheSurfaceByTextureCoordinates) {
  const std::string dir = test::temp_dir("texture");
  Image tex(2, 1, {"R", "G", "B"});
  tex.at(0, 0, 0) = 1.0f;  // left texel red
  tex.at(1, 0, 1) = 1.0f;  // right texel green
  write_image(dir + "/tex.exr", tex);
  const Image img =
      test::render_headon_quad(dir, "newmtl textured\nKd 1 1 1\nmap_Kd tex.exr\nillum 1\n",
                               "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl textured\nf 1/1 2/2 3/3 4/4\n");
  // Pixel centre -> world x on the quad -> u. Bilinear lookup with repeat wrapping between the texel
  // centres u = 0.25 (red) and 0.75 (green): red weight = 1 - (distance from u to the nearest red
  // centre 0.25 + k) / 0.5.
  const int checked = test::for_each_quad_column(img, [&](int px, double x) {
    const double u = (x + 1.0) / 2.0;
    const double d = std::abs(u - 0.25 - std::round(u - 0.25));
    const double red = 1.0 - d / 0.5;
    test::expect_quad_colour(img, px, red, 1.0 - red, 0.0, "u " + std::to_string(u));
  });
  EXPECT_GE(checked, 10);
  EXPECT_NEAR(img.at(2, test::kQuadRow, 0), 0.0f, 1e-6f) << "background outside the quad";
}

}  // namespace
}  // namespace rayvec
