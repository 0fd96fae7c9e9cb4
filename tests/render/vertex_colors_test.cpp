// Vertex colours (`v x y z r g b`): interpolated across each triangle, they multiply the diffuse
// albedo. A quad, red on the left and green on the right, lit head-on (headon_quad.h), reads back as
// Kd times the colour; in the scene, objects without colours stay white beside one with them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/image_io.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "scene/transform.h"
#include "headon_quad.h"
#include "test_support.h"

namespace rayvec {
namespace {

TEST(VertexColors, MultiplyTheDiffuseAlbedoAcrossTheSurface) {
  const std::string dir = test::temp_dir("vertex_colors");
  const Image img = test::render_headon_quad(dir, "newmtl m\nKd 0.5 1 1\nillum 1\n",
                                             "mtllib quad.mtl\nv -1 -1 0 1 0 0\nv 1 -1 0 0 1 0\nv 1 1 0 0 1 "
                                             "0\nv -1 1 0 1 0 0\nusemtl m\nf 1 2 3 4\n");
  const int checked = test::for_each_quad_column(img, [&](int px, double x) {
    const double green = (x + 1.0) / 2.0;  // the colour runs linearly from the left edge to the right
    test::expect_quad_colour(img, px, 0.5 * (1.0 - green), green, 0.0, "Kd 0.5 1 1 times the colour");
  });
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
  ASSERT_EQ(scene.warnings.size(), 1u) << "the colour above 1";
  EXPECT_EQ(scene.warnings[0],
            "vertex colours above 1 (up to 2) are clamped to 1: OBJ colours run from 0 to 1");
}

TEST(VertexColors, ColoursWrittenAsBytesAreClampedWithAWarningNamingTheFile) {
  const std::string dir = test::temp_dir("vertex_colors_255");
  test::write_file(dir + "/m.obj", "v 0 0 0 255 0 0\nv 1 0 0 0 128 0\nv 0 1 0 0 0 64\nf 1 2 3\n");
  const auto r =
      test::run_cli("render '" + dir + "/m.obj' -o '" + dir + "/m.png' --width 8 --height 8 --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(dir + "/m.obj: vertex colours above 1 (up to 255) are clamped to 1: OBJ colours run "
                             "from 0 to 1 (divide colours written as 0..255 by 255)"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rayvec
