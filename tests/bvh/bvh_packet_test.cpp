// Ray packets (BvhAccelerator::closest_stream) must give every lane exactly its single-ray answer and brute
// force's: same triangle id and bit-identical t, u, v (ties to the lowest id). With the float `mt`
// and `watertight` tables the leaves of AVX2/AVX-512 packets go through a ray-packet kernel
// (bvh/packet_leaf.inl, bvh/watertight_packet_leaf.inl: one triangle against all lanes per step);
// `mt` packets whose lanes mix tmin = 0 and tmin != 0, and `paper`, take the per-lane fallback,
// tested here too (more watertight cases: bvh_watertight_packet_test.cpp). Every ISA this CPU has; the
// others are skipped and named (scalar has no packets: its stream is single rays).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"
#include "bvh/bvh_traversal.h"
#include "bvh_cases.h"
#include "bvh_stream_check.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

using Case = test::BvhCase;

// A pinhole camera at `eye` looking down −z, w×h pixels (multiples of 4) as 4×4 tiles: consecutive
// groups of 16 rays (two 8-ray AVX2 packets per tile), all from one origin.
std::vector<Ray> camera_tiles(Vec3f eye, int w, int h, float half_width, float tmin = 0.0f) {
  std::vector<Ray> rays;
  for (int ty = 0; ty < h; ty += 4)
    for (int tx = 0; tx < w; tx += 4)
      for (int k = 0; k < 16; ++k) {
        const float x = (float(tx + k % 4) + 0.5f) / float(w) * 2.0f - 1.0f;
        const float y = (float(ty + k / 4) + 0.5f) / float(h) * 2.0f - 1.0f;
        rays.push_back(Ray{eye, {x * half_width, y * half_width, -1.0f}, tmin});
      }
  return rays;
}

class BvhPacket : public test::BvhCaseTest {
 protected:
  // closest_stream over rays[0..n) against closest() per ray and brute force; returns the hits.
  int expect_exact(const TriangleMesh& mesh, const std::vector<Ray>& rays,
                   std::optional<SahConfig> sah = std::nullopt) {
    BvhOptions options;
    if (sah) {
      options.sah = *sah;
      options.leaves_from_kernel = false;
    }
    options.width = GetParam().width;
    const BvhAccelerator bvh(mesh, config(), options);
    const BruteForce brute(mesh, config());
    return test::expect_stream_exact(bvh, brute, rays);
  }
};

TEST_P(BvhPacket, CameraTilesBitExactOnRandomSoupsWithDuplicates) {
  const TriangleMesh soup = test::random_soup(3000, 0.15f, 21);  // every 17th a duplicate
  const std::vector<Ray> rays = camera_tiles({0.1f, -0.05f, 2.5f}, 48, 48, 0.5f);
  EXPECT_GT(expect_exact(soup, rays), 1000);
  SahConfig big;  // 32-triangle leaves: many steps of the packet kernel per leaf
  big.max_leaf = 32;
  big.leaf_block = 16;
  EXPECT_GT(expect_exact(soup, rays, big), 1000);
}

// Long triangles referenced in several leaves (spatial splits): packets equal single rays.
TEST_P(BvhPacket, CameraTilesBitExactWithSpatialSplits) {
  const std::vector<Ray> rays = camera_tiles({0.1f, 0.3f, 2.5f}, 48, 48, 0.6f);
  EXPECT_GT(expect_exact(test::long_slivers(3000, 33), rays), 500);
}

TEST_P(BvhPacket, EveryLaneHitsFromInsideAClosedSphere) {
  const std::vector<Ray> rays = camera_tiles({0.05f, 0.02f, 0.1f}, 32, 32, 1.5f);
  EXPECT_EQ(expect_exact(test::sphere(1.0f, 24, 32), rays), int(rays.size()));
}

// Rays aimed exactly at grid vertices and edge midpoints hit 2 or 6 triangles at the same t; the
// grid twice (coincident triangles, different ids) doubles every tie. The lowest id must win.
TEST_P(BvhPacket, EdgeAndVertexTiesGoToTheLowestId) {
  TriangleMesh grid = test::flat_grid(6);
  const TriangleMesh copy = test::flat_grid(6);
  for (const auto& t : copy.triangles)
    grid.add_triangle(copy.positions[t[0]], copy.positions[t[1]], copy.positions[t[2]]);
  std::vector<Ray> rays;
  const Vec3f eye{3.0f, 3.0f, 4.0f};
  for (int y = 0; y <= 12; ++y)
    for (int x = 0; x <= 12; ++x) {
      const Vec3f target{float(x) * 0.5f, float(y) * 0.5f, 0.0f};
      rays.push_back(Ray{eye, target - eye});
    }
  EXPECT_GT(expect_exact(grid, rays), 100);
}

// Per-lane tmin > 0 and tmax exactly at, or one ulp around, each lane's single-ray hit: the
// interval is closed ([tmin, tmax]), so t == tmax and t == tmin hit and one ulp outside does not.
TEST_P(BvhPacket, PerLaneTminAndTmaxLimitsAtTheHitDistance) {
  const TriangleMesh soup = test::random_soup(2000, 0.2f, 22);
  const std::vector<Ray> base = camera_tiles({0.0f, 0.0f, 2.5f}, 32, 32, 0.5f, 0.25f);
  const BvhAccelerator probe(soup, config());
  std::vector<Ray> rays = base;
  int limited = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit h = probe.closest(base[i]);
    if (!h.hit()) continue;
    ++limited;
    switch (i % 5) {
      case 0: rays[i].tmax = h.t; break;
      case 1: rays[i].tmax = std::nextafter(h.t, 0.0f); break;
      case 2: rays[i].tmin = h.t; break;
      case 3: rays[i].tmin = std::nextafter(h.t, kInf); break;
      default: rays[i].tmin = 0.5f + 0.01f * float(i % 7); break;
    }
  }
  ASSERT_GT(limited, 200);
  expect_exact(soup, rays);
}

// Partially active packets: untraceable lanes, a stream that is not a multiple of the packet
// width, lanes mixing tmin = 0 and tmin > 0 (the per-lane fallback), scattered lanes.
TEST_P(BvhPacket, PartialAndMixedPacketsMatchSingleRays) {
  const TriangleMesh soup = test::random_soup(2000, 0.2f, 23);
  std::vector<Ray> rays = camera_tiles({0.0f, 0.1f, 2.5f}, 32, 32, 0.6f);
  for (std::size_t i = 0; i < rays.size(); i += 37) rays[i].org.x = std::nanf("");
  for (std::size_t i = 64; i < 128; i += 3) rays[i].tmin = 0.1f;  // mixed tmin packets
  for (std::size_t i = 128; i < 192; ++i)
    if (i % 16 > 2) rays[i].dir = {std::nanf(""), 0, 0};                    // packets with 3 live lanes
  for (const Ray& r : test::random_rays(300, 1.5f, 24)) rays.push_back(r);  // diverging packets
  rays.resize(rays.size() - 5);
  EXPECT_GT(expect_exact(soup, rays), 200);
}

// Lanes parallel to axes (1/d = ±inf) with origins on the planes of the root box, where a slab is
// 0·inf = NaN: the packet's root-box pre-test and box tests must not drop a lane that single rays
// hit (flat grid z = 0 over [0, 8]^2: vertical rays on the box's sides, in-plane rays, −0).
TEST_P(BvhPacket, AxisParallelLanesOnTheRootBoxPlanes) {
  const TriangleMesh grid = test::flat_grid(8);
  std::vector<Ray> rays;
  for (int i = 0; i < 64; ++i) {
    const float s = float(i) * 0.125f;
    rays.push_back(Ray{{s, 0.0f, 1.0f}, {0.0f, -0.0f, -1.0f}});
    rays.push_back(Ray{{8.0f, s, 2.0f}, {-0.0f, 0.0f, -1.0f}});
    rays.push_back(Ray{{-1.0f, s, 0.0f}, {1.0f, 0.0f, -0.0f}});
    rays.push_back(Ray{{s, 9.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
  }
  EXPECT_GT(expect_exact(grid, rays), 100);
}

INSTANTIATE_TEST_SUITE_P(AllIsasIntersectorsWidths, BvhPacket,
                         ::testing::ValuesIn(test::bvh_cases({Intersector::mt, Intersector::paper,
                                                              Intersector::watertight})),
                         test::bvh_case_name);

}  // namespace
}  // namespace rayvec
