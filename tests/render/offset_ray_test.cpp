// Secondary rays leave their surface: at every scale from 1e-4 to 1e5, rays spawned from hit points
// with offset_ray_origin (Wächter & Binder 2019) never hit the triangle they start on — no epsilon
// tuned per scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "accel/accelerator.h"
#include "render/offset_ray.h"
#include "geometry/triangle_mesh.h"
#include "platform/isa.h"

namespace rayvec {
namespace {

Vec3f random_unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  for (;;) {
    const Vec3f v{g(rng), g(rng), g(rng)};
    if (length(v) > 1e-3f) return normalize(v);
  }
}

// Random triangles of size ~scale placed ~scale·3 from the origin (so coordinates have the
// scale's magnitude) and also straddling the origin.
TriangleMesh random_triangles(std::mt19937& rng, float scale, int n) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i) {
    const Vec3f centre = Vec3f{u(rng), u(rng), u(rng)} * (i % 2 ? 3.0f * scale : 0.2f * scale);
    mesh.add_triangle(centre + Vec3f{u(rng), u(rng), u(rng)} * scale,
                      centre + Vec3f{u(rng), u(rng), u(rng)} * scale,
                      centre + Vec3f{u(rng), u(rng), u(rng)} * scale);
  }
  return mesh;
}

TEST(OffsetRay, SpawnedRaysNeverReHitTheirSurfaceAtAnyScale) {
  for (float scale : {1e-4f, 1e-2f, 1.0f, 1e2f, 1e5f}) {
    std::mt19937 rng(42);
    const TriangleMesh mesh = random_triangles(rng, scale, 64);
    for (Intersector is : {Intersector::mt, Intersector::mt64}) {
      const auto accel = make_accelerator(AccelKind::brute, mesh, TraceConfig{Isa::scalar, is});
      int tested = 0, rehits = 0;
      std::uniform_real_distribution<float> bary(0.0f, 1.0f);
      for (std::size_t t = 0; t < mesh.size(); ++t) {
        const Vec3f v0 = mesh.vertex(t, 0), e1 = mesh.vertex(t, 1) - v0, e2 = mesh.vertex(t, 2) - v0;
        const Vec3f n = normalize(cross(e1, e2));
        for (int k = 0; k < 64; ++k) {
          float a = bary(rng), b = bary(rng);
          if (a + b > 1) {
            a = 1 - a;
            b = 1 - b;
          }
          const Vec3f p = v0 + e1 * a + e2 * b;
          // Leave on either side, as reflection (same side) and refraction (other side) rays do.
          const Vec3f side = (k % 2) ? n : -n;
          Vec3f dir = random_unit(rng);
          if (dot(dir, side) < 0) dir = -dir;
          if (dot(dir, side) < 1e-3f) continue;  // grazing: skip degenerate directions
          const Hit h = accel->closest(Ray{offset_ray_origin(p, side), dir, 0.0f, kInf});
          ++tested;
          if (h.tri == static_cast<int32_t>(t)) ++rehits;
        }
      }
      EXPECT_GT(tested, 3000);
      EXPECT_EQ(rehits, 0) << "scale " << scale << " " << intersector_name(is);
    }
  }
}

// Shadow rays from a large floor toward lights from grazing to steep (a room's floor): when the
// ray's dominant axis lies along the floor, the watertight kernels' t is formed from vertices
// hundreds of units away and carries a rounding error far larger than the few-ulp offset; without
// their error bound on t they report the floor itself at t = -0 or 1e-8 (speckled shadows).
TEST(OffsetRay, ShadowRaysNeverReHitALargeFloor) {
  TriangleMesh floor;
  floor.add_triangle({0, 0, 0}, {0, 0, 560}, {556, 0, 560});
  floor.add_triangle({0, 0, 0}, {556, 0, 560}, {556, 0, 0});
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (Isa isa : kAllIsas) {
    if (!isa_supported(isa)) {
      std::printf("skipped ISA %s: not on this CPU\n", isa_name(isa));
      continue;
    }
    for (Intersector is :
         {Intersector::mt, Intersector::mt64, Intersector::watertight, Intersector::watertight64}) {
      const auto accel = make_accelerator(AccelKind::brute, floor, TraceConfig{isa, is});
      int rehits = 0;
      for (int k = 0; k < 4000; ++k) {
        const Vec3f p{556 * u(rng), 0.0f, 560 * u(rng)};
        // toward a light 400..1200 units away, 0.01 to 80 degrees above the floor
        const float azimuth = 6.2831853f * u(rng), elevation = (0.01f + 80.0f * u(rng)) * 0.0174533f;
        const float dist = 400 + 800 * u(rng);
        const Vec3f dir = Vec3f{std::cos(azimuth) * std::cos(elevation), std::sin(elevation),
                                std::sin(azimuth) * std::cos(elevation)} *
                          dist;
        const Hit h = accel->closest(Ray{offset_ray_origin(p, {0, 1, 0}), dir, 0.0f, 0.99999f});
        if (h.hit()) ++rehits;
      }
      EXPECT_EQ(rehits, 0) << intersector_name(is) << " " << isa_name(isa);
    }
  }
}

TEST(OffsetRay, OffsetIsSmallRelativeToTheCoordinate) {
  for (float c : {1e-4f, 0.5f, 1.0f, 1e3f, 1e5f, -7e4f}) {
    const Vec3f p{c, -c, c};
    const Vec3f n = normalize(Vec3f{1, 1, 1});
    const Vec3f o = offset_ray_origin(p, n);
    for (int i = 0; i < 3; ++i) {
      EXPECT_GT(o[i], p[i]) << c;  // moves along the normal
      EXPECT_LT(std::fabs(o[i] - p[i]), std::max(1e-4f * std::fabs(p[i]), 1e-4f)) << c;
    }
  }
}

// Next to zero the absolute offset applies, including at −0 and the negative denormals, whose bit
// patterns sit at the bottom of int32 (moving them by ulps overflowed a signed sum: UBSan's stage
// catches that).
TEST(OffsetRay, CoordinatesNextToZeroTakeTheAbsoluteOffset) {
  for (float c : {-0.0f, 0.0f, -1e-45f, 1e-45f, -1e-38f, -0.03f}) {
    for (float s : {1.0f, -1.0f}) {
      const Vec3f n = normalize(Vec3f{s, -s, s});
      const Vec3f o = offset_ray_origin(Vec3f{c, c, c}, n);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(o[i], c + (1.0f / 65536.0f) * n[i]) << c << " " << s << " " << i;
        EXPECT_TRUE(std::isfinite(o[i]));
      }
    }
  }
}

}  // namespace
}  // namespace rayvec
