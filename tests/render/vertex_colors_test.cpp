// Vertex colours (`v x y z r g b`): interpolated across each triangle, they multiply the diffuse
// albedo. A quad, red on the left and green on the right, lit head-on by a directional light of
// irradiance pi, reads back as Kd times the colour (Lambert: Kd·c/pi · E·cos 0), rendered through the
// CLI; in the scene, objects without colours stay white beside one with them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/image_io.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "scene/transform.h"
#include "test_support.h"

namespace rayvec {
namespace {

TEST(VertexColors, MultiplyTheDiffuseAlbedoAcrossTheSurface) {
  const std::string dir = test::temp_dir("vertex_colors");
  test::write_file(dir + "/quad.mtl", "newmtl m\nKd 0.5 1 1\nillum 1\n");
  test::write_file(dir + "/quad.obj",
                   "mtllib quad.mtl\nv -1 -1 0 1 0 0\nv 1 -1 0 0 1 0\nv 1 1 0 0 1 0\nv -1 1 0 1 0 0\n"
                   "usemtl m\nf 1 2 3 4\n");
  const std::string pi = std::to_string(3.14159265f);
  test::write_file(dir + "/scene.json",
                   "{ \"camera\": { \"eye\": [0, 0, 3], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0],"
                   " \"fov_y\": 60, \"width\": 40, \"height\": 20 },"
                   " \"background\": [0, 0, 0], \"ambient\": [0, 0, 0],"
                   " \"lights\": [ { \"type\": \"directional\", \"direction\": [0, 0, -1],"
                   " \"irradiance\": [" +
                       pi + ", " + pi + ", " + pi +
                       "] } ],"
                       " \"objects\": [ { \"obj\": \"quad.obj\" } ], \"render\": { \"spp\": 1 } }");
  const auto r = test::run_cli("render '" + dir + "/scene.json' -o '" + dir + "/out.exr' --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const Image img = read_image(dir + "/out.exr");
  ASSERT_EQ(img.width, 40);
  const double half_width = 3.0 * std::tan(30.0 * 3.141592653589793 / 180.0) * 2.0;
  int checked = 0;
  for (int px = 0; px < 40; ++px) {
    const double x = ((px + 0.5) / 40.0 * 2.0 - 1.0) * half_width;
    if (std::abs(x) > 0.95) continue;      // off the quad or on its silhouette
    const double green = (x + 1.0) / 2.0;  // the colour runs linearly from the left edge to the right
    EXPECT_NEAR(img.at(px, 10, 0), 0.5 * (1.0 - green), 2e-3) << "pixel " << px;
    EXPECT_NEAR(img.at(px, 10, 1), green, 2e-3) << "pixel " << px;
    EXPECT_NEAR(img.at(px, 10, 2), 0.0, 1e-6) << "pixel " << px;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

ObjModel triangle(std::vector<Vec3f> colors = {}) {
  ObjModel m;
  m.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.mesh.triangles = {{0, 1, 2}};
  m.triangle_material = {-1};
  m.colors = std::move(colors);
  return m;
}

TEST(VertexColors, ObjectsWithoutColoursStayWhiteAndColoursAreClamped) {
  Scene scene;
  scene.add_object(triangle(), Transform{});
  EXPECT_FALSE(scene.colors(0).has_value()) << "no object with colours: none";
  scene.add_object(triangle({{2, -1, 0.5f}, {NAN, 0, 1}, {0.25f, 0.5f, 0.75f}}), Transform{});
  scene.add_object(triangle(), Transform{});
  const auto white = std::array<Vec3f, 3>{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}, Vec3f{1, 1, 1}};
  ASSERT_TRUE(scene.colors(0).has_value());
  EXPECT_EQ(*scene.colors(0), white) << "the object before";
  EXPECT_EQ(*scene.colors(2), white) << "the object after";
  const auto c = *scene.colors(1);
  EXPECT_EQ(c[0], (Vec3f{1, 0, 0.5f})) << "clamped to [0, 1]";
  EXPECT_EQ(c[1], (Vec3f{0, 0, 1})) << "NaN reads as 0";
  EXPECT_EQ(c[2], (Vec3f{0.25f, 0.5f, 0.75f}));
}

}  // namespace
}  // namespace rayvec
