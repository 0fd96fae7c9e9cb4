// Properties of the watertight intersectors (Woop, Benthin & Wald 2013) that need no oracle: rays
// through the shared diagonal of a quad never slip through, and every ISA gives the same answer.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "accel/accelerator.h"
#include "accuracy/hard_cases.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

constexpr Intersector kWatertightModes[] = {Intersector::watertight, Intersector::watertight64};

Hit closest(Isa isa, Intersector in, const TriangleSoA& soa, const Ray& ray) {
  Hit hit;
  triangle_kernels(isa, in).closest(soa.arrays(), 0, soa.size(), ray, hit);
  return hit;
}

// A quad with irrational-looking corners split along its diagonal a–c; rays aimed at points of the
// diagonal from random origins.
TriangleMesh diagonal_quad() {
  TriangleMesh m;
  m.positions = {{-1.1f, -0.93f, 2.7f}, {1.3f, -1.07f, 3.1f}, {0.97f, 1.21f, 2.2f}, {-0.89f, 1.03f, 1.9f}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(Watertight, RaysThroughSharedDiagonalNeverSlipThrough) {
  const TriangleMesh mesh = diagonal_quad();
  const TriangleSoA soa(mesh);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> s(0.05f, 0.95f), o(-3.0f, 3.0f);
  const Vec3f a = mesh.positions[0], c = mesh.positions[2];
  for (Isa isa : supported_isas())
    for (Intersector in : kWatertightModes)
      for (int k = 0; k < 2000; ++k) {
        const float f = s(rng);
        const Vec3f p{a.x + f * (c.x - a.x), a.y + f * (c.y - a.y), a.z + f * (c.z - a.z)};
        const Vec3f org{o(rng), o(rng), -2.0f};
        const Ray ray{org, {p.x - org.x, p.y - org.y, p.z - org.z}};
        const Hit hit = closest(isa, in, soa, ray);
        ASSERT_GE(hit.tri, 0) << isa_name(isa) << " " << intersector_name(in) << " ray " << k;
        EXPECT_NEAR(hit.t, 1.0f, 1e-4f);
        EXPECT_FALSE(std::isnan(hit.u) || std::isnan(hit.v));
      }
}

TEST(Watertight, SameAnswerOnEveryIsa) {
  TriangleMesh mesh;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int k = 0; k < 37; ++k) {
    const Vec3f c{u(rng), u(rng), 3.0f + u(rng)};
    mesh.add_triangle({c.x + u(rng), c.y + u(rng), c.z + 0.1f * u(rng)},
                      {c.x + u(rng), c.y + u(rng), c.z + 0.1f * u(rng)},
                      {c.x + u(rng), c.y + u(rng), c.z + 0.1f * u(rng)});
  }
  const TriangleSoA soa(mesh);
  for (Intersector in : kWatertightModes)
    for (int k = 0; k < 500; ++k) {
      const Ray ray{{0.1f * u(rng), 0.1f * u(rng), 0}, {u(rng), u(rng), 1.0f + u(rng)}};
      const Hit ref = closest(Isa::scalar, in, soa, ray);
      for (Isa isa : supported_isas()) {
        const Hit hit = closest(isa, in, soa, ray);
        EXPECT_EQ(hit.tri, ref.tri) << isa_name(isa);
        EXPECT_EQ(hit.t, ref.t) << isa_name(isa);
      }
    }
}

// A ray through a vertex shared by a fan: an edge function is exactly 0 in float, so the double
// fallback decides; some triangle of the fan must still be hit.
TEST(Watertight, RayThroughFanCentreHits) {
  TriangleMesh mesh;
  const Vec3f c{0.3f, 0.7f, 5.0f};
  const int n = 7;
  for (int k = 0; k < n; ++k) {
    const float a0 = 6.2831853f * float(k) / n, a1 = 6.2831853f * float(k + 1) / n;
    mesh.add_triangle(c, {c.x + std::cos(a0), c.y + std::sin(a0), c.z + 0.3f * std::sin(3 * a0)},
                      {c.x + std::cos(a1), c.y + std::sin(a1), c.z + 0.3f * std::sin(3 * a1)});
  }
  const TriangleSoA soa(mesh);
  for (Isa isa : supported_isas())
    for (Intersector in : kWatertightModes) {
      const Hit hit = closest(isa, in, soa, Ray{{c.x, c.y, 0}, {0, 0, 1}});
      ASSERT_GE(hit.tri, 0) << isa_name(isa) << " " << intersector_name(in);
      EXPECT_EQ(hit.t, 5.0f);
    }
}

// Rays from inside a 5,120-triangle closed sphere through its exact vertices, through the BVH (whose
// box tests must not lose them either) and brute force. Float Möller–Trumbore loses several percent
// of these; the watertight modes none.
TEST(Watertight, VertexRaysFromInsideAClosedSphereNeverEscape) {
  for (const Vec3d centre : {Vec3d{0.3, -0.2, 0.1}, Vec3d{148376, 1234, -223423}}) {
    const double radius = centre.x > 1000 ? 200.0 : 1.0;
    const TriangleMesh mesh = make_icosphere(centre, radius, 4, 99);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (std::size_t k = 0; k < 4000; ++k) {
      const Vec3f org(centre + Vec3d{u(rng), u(rng), u(rng)} * (0.3 * radius));
      rays.push_back(Ray{org, Vec3f(Vec3d(mesh.positions[k % mesh.positions.size()]) - Vec3d(org))});
    }
    for (AccelKind kind : {AccelKind::brute, AccelKind::bvh})
      for (Isa isa : supported_isas())
        for (Intersector in : kWatertightModes) {
          std::unique_ptr<Accelerator> accel;
          try {
            accel = make_accelerator(kind, mesh, {isa, in});
          } catch (const std::exception&) {
            continue;  // accelerator not available in this build
          }
          std::size_t escaped = 0;
          for (const Ray& r : rays) escaped += !accel->closest(r).hit();
          EXPECT_EQ(escaped, 0u) << accel_name(kind) << " " << isa_name(isa) << " " << intersector_name(in)
                                 << " centre.x " << centre.x;
        }
  }
}

}  // namespace
}  // namespace rayvec
