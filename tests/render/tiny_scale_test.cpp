// Tiny geometry: the geometric normal of a triangle a few 1e-12 across (whose cross product's
// squared length underflows float) is still a finite unit vector facing the ray, and a scene
// smaller than the range the secondary-ray offsets are tested for (1e-4, offset_ray_test.cpp) is
// refused at load time instead of rendering black with NaN normals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/surface_point.h"
#include "scene/scene.h"
#include "test_support.h"

namespace rayvec {
namespace {

// Triangle 0 of `scene` hit at (u, v) = (0.25, 0.5) by a ray along +z.
SurfacePoint point_seen_along_z(const Scene& scene) {
  const Ray ray{{0, 0, -1}, {0, 0, 1}, 0, 1e30f};
  Hit hit;
  hit.tri = 0;
  hit.t = 1;
  hit.u = 0.25f;
  hit.v = 0.5f;
  return surface_point(scene, ray, hit);
}

TEST(TinyScale, GeometricNormalIsAFiniteUnitVectorAtEveryScale) {
  // subnormal vertices (1e-40) to edges near float's largest value (1e37)
  for (float scale : {1e-40f, 1e-30f, 1e-20f, 1e-12f, 1e-6f, 1.0f, 1e10f, 1e30f, 1e37f}) {
    Scene scene;
    const int32_t mat = scene.add_material(Material{});
    scene.add_triangle(Vec3f{-1, -1, 0} * scale, Vec3f{1, -1, 0} * scale, Vec3f{0, 1, 0} * scale, mat);
    const SurfacePoint s = point_seen_along_z(scene);
    for (const Vec3f n : {s.ng, s.ns}) {
      EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << scale;
      EXPECT_NEAR(n.z, -1.0f, 1e-6f) << scale << ": the normal faces the incoming ray";
    }
  }
}

TEST(TinyScale, ShadingNormalIsAFiniteUnitVectorForAnyVertexNormalLength) {
  for (float length : {1e-40f, 1e-30f, 1.0f, 1e30f, 3e38f}) {
    Scene scene;
    const int32_t mat = scene.add_material(Material{});
    scene.add_triangle(Vec3f{-1, -1, 0}, Vec3f{1, -1, 0}, Vec3f{0, 1, 0}, mat);
    scene.set_normals(0, {Vec3f{0, 0, length}, Vec3f{0, 0, length}, Vec3f{0, 0, length}});
    const Vec3f n = point_seen_along_z(scene).ns;
    EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << length;
    EXPECT_NEAR(n.z, -1.0f, 1e-6f) << length << ": the shading normal is unit length and faces the ray";
  }
}

TEST(TinyScale, ScenesBelowTheOffsetRangeAreRefused) {
  const std::string dir = test::temp_dir("tiny_scene");
  test::write_file(dir + "/m.obj", "v -1e-12 -1e-12 0\nv 1e-12 -1e-12 0\nv 0 1e-12 0\nf 1 2 3\n");
  auto r = test::run_cli("render -q " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/out.png");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(dir + "/m.obj: the scene is 2e-12 across"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("below 0.0001"), std::string::npos) << r.err;
  test::write_file(dir + "/s.json", "{\"objects\": [{\"obj\": \"m.obj\", \"transform\": {\"scale\": 1e8}}]}");
  r = test::run_cli("render -q " + dir + "/s.json --width 8 --height 8 -o " + dir + "/out.png");
  EXPECT_EQ(r.status, 0) << r.err;  // 2e-4 across: scaled into the range by its transform
  // A scene of one point cannot be scaled into the range: it is refused as empty, not as small.
  test::write_file(dir + "/p.obj", "v 3 3 3\nv 3 3 3\nv 3 3 3\nf 1 2 3\n");
  r = test::run_cli("render -q " + dir + "/p.obj --width 8 --height 8 -o " + dir + "/out.png");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("all lie at one point (0 across): there is nothing to render"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rayvec
