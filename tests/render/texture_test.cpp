// map_Kd textures: an OBJ quad with texture coordinates and an MTL map_Kd, rendered through the CLI.
// A 2x1 linear EXR texture (left texel red, right texel green) lit head-on by a directional light of
// irradiance pi reads back as the bilinearly filtered texel colour (Lambert: Kd·tex/pi · E·cos 0).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/image_io.h"
#include "test_support.h"

namespace rayvec {
namespace {

TEST(Texture, MapKdColoursTheSurfaceByTextureCoordinates) {
  const std::string dir = test::temp_dir("texture");
  Image tex(2, 1, {"R", "G", "B"});
  tex.at(0, 0, 0) = 1.0f;  // left texel red
  tex.at(1, 0, 1) = 1.0f;  // right texel green
  write_image(dir + "/tex.exr", tex);
  test::write_file(dir + "/quad.mtl", "newmtl textured\nKd 1 1 1\nmap_Kd tex.exr\nillum 1\n");
  test::write_file(dir + "/quad.obj",
                   "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl textured\nf 1/1 2/2 3/3 4/4\n");
  const float pi = 3.14159265f;
  test::write_file(dir + "/scene.json",
                   "{ \"camera\": { \"eye\": [0, 0, 3], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0],"
                   " \"fov_y\": 60, \"width\": 40, \"height\": 20 },"
                   " \"background\": [0, 0, 0], \"ambient\": [0, 0, 0],"
                   " \"lights\": [ { \"type\": \"directional\", \"direction\": [0, 0, -1],"
                   " \"irradiance\": [" +
                       std::to_string(pi) + ", " + std::to_string(pi) + ", " + std::to_string(pi) +
                       "] } ],"
                       " \"objects\": [ { \"obj\": \"quad.obj\" } ],"
                       " \"render\": { \"spp\": 1 } }");
  const auto r = test::run_cli("render '" + dir + "/scene.json' -o '" + dir + "/out.exr' --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const Image img = read_image(dir + "/out.exr");
  ASSERT_EQ(img.width, 40);
  // Pixel centre -> world x on the quad (z = 0, camera at distance 3, half-width 3·tan 30°·2) -> u.
  // Bilinear lookup with repeat wrapping between the texel centres u = 0.25 (red) and 0.75 (green):
  // red weight = 1 - (distance from u to the nearest red centre 0.25 + k) / 0.5.
  const double half_width = 3.0 * std::tan(30.0 * 3.141592653589793 / 180.0) * 2.0;
  int checked = 0;
  for (int px = 0; px < 40; ++px) {
    const double x = ((px + 0.5) / 40.0 * 2.0 - 1.0) * half_width;
    if (std::abs(x) > 0.95) continue;  // off the quad or on its silhouette
    const double u = (x + 1.0) / 2.0;
    const double d = std::abs(u - 0.25 - std::round(u - 0.25));
    const double red = 1.0 - d / 0.5;
    EXPECT_NEAR(img.at(px, 10, 0), red, 2e-3) << "pixel " << px << " u " << u;
    EXPECT_NEAR(img.at(px, 10, 1), 1.0 - red, 2e-3) << "pixel " << px << " u " << u;
    EXPECT_NEAR(img.at(px, 10, 2), 0.0, 1e-6);
    ++checked;
  }
  EXPECT_GE(checked, 10);
  EXPECT_NEAR(img.at(2, 10, 0), 0.0f, 1e-6f) << "background outside the quad";
}

}  // namespace
}  // namespace rayvec
