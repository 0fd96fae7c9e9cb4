// AffineMap: world_from_object = translate · Rz · Ry · Rx · scale, right-handed rotations in
// degrees; normals by the inverse transpose; mirrors flip the winding.
#include <gtest/gtest.h>

#include <random>

#include "scene/transform.h"

namespace rayvec {
namespace {

void expect_near(Vec3f a, Vec3f b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(AffineMap, RotationsAreRightHandedAndApplyXThenYThenZ) {
  expect_near(AffineMap(Transform{{1, 1, 1}, {90, 0, 0}, {}}).point({0, 1, 0}), {0, 0, 1});
  expect_near(AffineMap(Transform{{1, 1, 1}, {0, 90, 0}, {}}).point({0, 0, 1}), {1, 0, 0});
  expect_near(AffineMap(Transform{{1, 1, 1}, {0, 0, 90}, {}}).point({1, 0, 0}), {0, 1, 0});
  // x first: (0, 1, 0) -x-> (0, 0, 1) -y-> (1, 0, 0) -z-> (0, 1, 0).
  expect_near(AffineMap(Transform{{1, 1, 1}, {90, 90, 90}, {}}).point({0, 1, 0}), {0, 1, 0});
}

TEST(AffineMap, ScaleFirstTranslateLast) {
  const AffineMap m(Transform{{2, 3, 4}, {0, 0, 90}, {10, 20, 30}});
  expect_near(m.point({1, 1, 1}), {10 - 3, 20 + 2, 30 + 4});
  EXPECT_FALSE(m.flips_orientation());
}

// The transformed normal stays perpendicular to the transformed surface, and is unit.
TEST(AffineMap, NormalStaysPerpendicularToTransformedTangents) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1), s(0.2f, 3), deg(-180, 180);
  for (int i = 0; i < 200; ++i) {
    Transform t;
    t.scale = {s(rng) * (i % 2 ? -1.0f : 1.0f), s(rng), s(rng)};
    t.rotate_deg = {deg(rng), deg(rng), deg(rng)};
    t.translate = {u(rng), u(rng), u(rng)};
    const AffineMap m(t);
    const Vec3f a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const Vec3f n = normalize(cross(b - a, c - a));
    const Vec3f e1 = normalize(m.point(b) - m.point(a)), e2 = normalize(m.point(c) - m.point(a));
    const Vec3f mn = m.normal(n);
    EXPECT_NEAR(length(mn), 1, 1e-5f);
    EXPECT_NEAR(dot(mn, e1), 0, 1e-3f);
    EXPECT_NEAR(dot(mn, e2), 0, 1e-3f);
  }
}

TEST(AffineMap, OddNumberOfMirrorsFlipsOrientation) {
  EXPECT_TRUE(AffineMap(Transform{{-1, 1, 1}, {}, {}}).flips_orientation());
  EXPECT_FALSE(AffineMap(Transform{{-1, -1, 1}, {}, {}}).flips_orientation());
  EXPECT_TRUE(AffineMap(Transform{{-1, -2, -3}, {30, 0, 0}, {}}).flips_orientation());
}

}  // namespace
}  // namespace rayvec
