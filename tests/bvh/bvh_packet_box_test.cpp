// The packet box tests of packet_traversal.inl: the forward test (every tmin >= 0: one FMA a slab with
// the widening folded into the reciprocals and o·r' rounded outward) for uniform-sign packets (the
// near plane the same for every lane) and mixed-sign ones, and the general test it falls back to
// (tmin < 0, a zero or −0 direction component, products that could overflow). Whichever test a
// packet takes, every lane must equal its single ray and brute force bit for bit — in particular
// far from the coordinate origin, where o·(1/d) is much larger than the distances to the boxes and
// an FMA slab without the outward rounding would lose boxes that rays aimed at vertices (box
// corners) just touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"
#include "bvh_cases.h"
#include "bvh_stream_check.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

class BvhPacketBox : public test::BvhCaseTest {
 protected:
  // closest_stream against closest() and brute force per ray; returns the number of hits.
  int expect_exact(const TriangleMesh& mesh, const std::vector<Ray>& rays) {
    BvhOptions options;
    options.width = GetParam().width;
    const BvhAccelerator bvh(mesh, config(), options);
    const BruteForce brute(mesh, config());
    return test::expect_stream_exact(bvh, brute, rays);
  }
};

TriangleMesh translated(TriangleMesh m, Vec3f by) {
  for (Vec3f& p : m.positions) p = p + by;
  return m;
}

// Rays from `eye` toward every mesh vertex (exactly on leaf box corners and faces), ordered by
// cells of `cell` units, so the 16 targets of a packet are near each other: a packet mixes
// direction signs only where its cell straddles a coordinate plane through the eye.
std::vector<Ray> rays_at_vertices(const TriangleMesh& m, Vec3f eye, float tmin, float cell = 0.25f) {
  std::vector<Vec3f> targets = m.positions;
  const Vec3f lo = targets.empty() ? eye : targets[0];
  auto key = [&](Vec3f p) {
    return std::make_tuple(int((p.z - lo.z) / cell + 1e4f), int((p.y - lo.y) / cell + 1e4f),
                           int((p.x - lo.x) / cell + 1e4f), p.x);
  };
  std::sort(targets.begin(), targets.end(), [&](Vec3f a, Vec3f b) { return key(a) < key(b); });
  std::vector<Ray> rays;
  for (const Vec3f& t : targets) rays.push_back(Ray{eye, t - eye, tmin});
  return rays;
}

// Does each packet of 16 share the signs of its direction components (the uniform forward test)?
int uniform_packets(const std::vector<Ray>& rays) {
  int n = 0;
  for (std::size_t i = 0; i + 16 <= rays.size(); i += 16) {
    bool same = true;
    for (std::size_t k = i + 1; k < i + 16; ++k)
      same = same && std::signbit(rays[k].dir.x) == std::signbit(rays[i].dir.x) &&
             std::signbit(rays[k].dir.y) == std::signbit(rays[i].dir.y) &&
             std::signbit(rays[k].dir.z) == std::signbit(rays[i].dir.z);
    n += same;
  }
  return n;
}

TEST_P(BvhPacketBox, UniformAndMixedSignPacketsAimedAtVertices) {
  const TriangleMesh soup = test::random_soup(2000, 0.2f, 41);
  // the eye inside the soup's box: packets toward vertices on both sides of it mix signs
  for (const Vec3f eye : {Vec3f{0.1f, 0.2f, 2.5f}, Vec3f{0.05f, -0.1f, 0.02f}}) {
    const std::vector<Ray> rays = rays_at_vertices(soup, eye, 0.0f);
    EXPECT_GT(expect_exact(soup, rays), 2000);
  }
  const std::vector<Ray> inside = rays_at_vertices(soup, {0.05f, -0.1f, 0.02f}, 0.0f);
  const int uniform = uniform_packets(inside);
  EXPECT_GT(uniform, 20);
  EXPECT_LT(uniform, int(inside.size() / 16) - 20);
}

// The mesh 10^4 away from the origin, the eye 3 units from it: |o·(1/d)| is thousands of times the
// box distances, so the rounding of o·r' is far larger than the widening eps·|t|.
TEST_P(BvhPacketBox, FarFromTheOriginVertexRaysKeepEveryBox) {
  const Vec3f far{9000.0f, -7000.0f, 12000.0f};
  const TriangleMesh soup = translated(test::random_soup(2000, 0.2f, 42), far);
  for (const Vec3f eye : {Vec3f{0.3f, 0.1f, 3.0f}, Vec3f{-2.5f, 1.0f, -1.5f}, Vec3f{0.0f, 0.0f, 0.0f}}) {
    const std::vector<Ray> rays = rays_at_vertices(soup, eye + far, 0.0f);
    EXPECT_GT(expect_exact(soup, rays), 2000);
  }
  const TriangleMesh grid = translated(test::flat_grid(16), far);  // vertices on shared box planes
  EXPECT_GT(expect_exact(grid, rays_at_vertices(grid, far + Vec3f{5.3f, 7.1f, 4.0f}, 0.0f)), 200);
}

// tmin > 0 (forward test, packet kernel without the tmin = 0 pre-test) and tmin < 0 (general test).
TEST_P(BvhPacketBox, PositiveAndNegativeTminPackets) {
  const TriangleMesh soup = test::random_soup(2000, 0.2f, 43);
  for (const float tmin : {0.5f, 1e-3f, -0.5f, -1e30f})
    EXPECT_GT(expect_exact(soup, rays_at_vertices(soup, {0.1f, 0.2f, 2.5f}, tmin)), 1000);
}

// Lanes whose direction has a +0 or −0 component (1/d = ±inf: the general test), alone in a packet
// of ordinary lanes or making up the whole packet, and packets whose every lane has tiny
// components (1/d large but finite: the guard against overflowing products).
TEST_P(BvhPacketBox, ZeroTinyAndNegativeZeroDirectionComponents) {
  const TriangleMesh grid = test::flat_grid(8);
  const TriangleMesh soup = test::random_soup(1500, 0.2f, 44);
  std::mt19937 rng(45);
  std::uniform_real_distribution<float> u(0.0f, 8.0f);
  for (const TriangleMesh* mesh : {&grid, &soup}) {
    std::vector<Ray> rays;
    for (int p = 0; p < 48; ++p)
      for (int k = 0; k < 16; ++k) {
        const Vec3f eye{u(rng) * 0.1f, u(rng) * 0.1f, 3.0f};
        Vec3f d{u(rng) - eye.x, u(rng) - eye.y, -3.0f};
        if (mesh == &soup) d = Vec3f{d.x * 0.25f, d.y * 0.25f, d.z};
        switch (p % 4) {
          case 0:
            if (k == 5) d.x = (p & 4) ? -0.0f : 0.0f;
            break;                                      // one lane
          case 1: d.y = (k & 1) ? -0.0f : 0.0f; break;  // every lane, both zeros
          case 2:
            d.x *= 1e-30f;
            d.y *= 1e-30f;
            break;  // 1/d ~ 1e30
          default: break;
        }
        rays.push_back(Ray{eye, d});
      }
    EXPECT_GT(expect_exact(*mesh, rays), 100);
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsasWidths, BvhPacketBox,
                         ::testing::ValuesIn(test::bvh_cases({Intersector::mt, Intersector::watertight})),
                         test::bvh_case_name);

}  // namespace
}  // namespace rayvec
