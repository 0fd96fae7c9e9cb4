// TriangleNormals: the table a render looks each hit's geometric normal up in gives surface_point
// what it computes without it, bit for bit — at every scale, for slivers and zero-area triangles,
// with and without vertex normals, from either side — and is made only where it pays.
#include <gtest/gtest.h>

#include <bit>
#include <random>

#include "render/surface_point.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

bool same_bits(Vec3f a, Vec3f b) {
  return std::bit_cast<uint32_t>(a.x) == std::bit_cast<uint32_t>(b.x) &&
         std::bit_cast<uint32_t>(a.y) == std::bit_cast<uint32_t>(b.y) &&
         std::bit_cast<uint32_t>(a.z) == std::bit_cast<uint32_t>(b.z);
}

TEST(TriangleNormals, LookedUpNormalsAreTheComputedOnes) {
  Scene scene;
  const int32_t mat = scene.add_material(Material{});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  auto point = [&](float scale) { return Vec3f{unit(rng), unit(rng), unit(rng)} * scale; };
  for (float scale : {1e-40f, 1e-20f, 1e-6f, 1.0f, 1e3f, 1e20f, 1e37f})
    for (int k = 0; k < 40; ++k) {
      const Vec3f a = point(scale), b = point(scale);
      scene.add_triangle(a, b, point(scale), mat);
      scene.add_triangle(a, b, a + (b - a) * 0.5f, mat);                         // zero area: collinear
      scene.add_triangle(a, b, a + (b - a) * 0.5f + point(scale * 1e-6f), mat);  // sliver
    }
  scene.set_normals(3, {Vec3f{0, 0, 1}, Vec3f{0, 1, 0}, Vec3f{1, 0, 0}});
  const TriangleNormals table(scene);
  ASSERT_FALSE(table.empty());
  for (std::size_t t = 0; t < scene.mesh.size(); ++t)
    for (const Vec3f dir : {Vec3f{0.3f, -0.2f, 1}, Vec3f{-0.3f, 0.2f, -1}}) {
      const Ray ray{{0, 0, 0}, dir, 0, kInf};
      Hit hit;
      hit.tri = int32_t(t);
      hit.t = 1;
      hit.u = 0.25f;
      hit.v = 0.5f;
      const SurfacePoint want = surface_point(scene, ray, hit), got = surface_point(scene, ray, hit, &table);
      ASSERT_TRUE(same_bits(got.ng, want.ng) && same_bits(got.ns, want.ns) && same_bits(got.p, want.p) &&
                  got.entering == want.entering)
          << "triangle " << t;
    }
}

TEST(TriangleNormals, MadeOnlyForMeshesNoLargerThanTheCameraRaysAndAQuarterOfFreeMemory) {
  EXPECT_TRUE(TriangleNormals::worth_it(3392, 640 * 480, 0));
  EXPECT_TRUE(TriangleNormals::worth_it(307200, 640 * 480, 0));
  EXPECT_FALSE(TriangleNormals::worth_it(998000, 640 * 480, 0));
  EXPECT_TRUE(TriangleNormals::worth_it(1000, 1 << 20, 48000));  // 12 kB of 48 kB
  EXPECT_FALSE(TriangleNormals::worth_it(1000, 1 << 20, 47999));
  EXPECT_TRUE(TriangleNormals(Scene{}).empty());
}

}  // namespace
}  // namespace rayvec
