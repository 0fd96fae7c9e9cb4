// The float `watertight` packet leaf (bvh/watertight_packet_leaf.inl): every lane of a packet must get
// exactly its single-ray answer (same id, bit-identical t, u, v) on the hard-case families, random rays
// and camera tiles of every ray permutation, and rays through the shared edges and vertices of closed
// meshes, which must all hit; and the packet traversal must really run that kernel for `watertight`
// (not the single-ray kernel lane by lane), while the double intersectors keep the per-lane fallback.
// Every ISA with packets this CPU has; the others are skipped and named.
#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "accel/bvh_accelerator.h"
#include "accuracy/hard_cases.h"
#include "bvh_cases.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

using BvhWatertightPacket = test::BvhPacketCaseTest;

// closest_stream over `rays` against closest() ray by ray, bit for bit; returns the hits.
int expect_lanes_exact(const BvhAccelerator& bvh, const std::vector<Ray>& rays, const std::string& what) {
  auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
  std::vector<Hit> stream(rays.size());
  bvh.closest_stream(rays.data(), stream.data(), rays.size());
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit want = bvh.closest(rays[i]);
    EXPECT_EQ(want.tri, stream[i].tri) << what << " ray " << i;
    EXPECT_EQ(bits(want.t), bits(stream[i].t))
        << what << " ray " << i << ": " << want.t << " vs " << stream[i].t;
    EXPECT_EQ(bits(want.u), bits(stream[i].u)) << what << " ray " << i;
    EXPECT_EQ(bits(want.v), bits(stream[i].v)) << what << " ray " << i;
    if (::testing::Test::HasFailure()) return hits;
    hits += stream[i].hit();
  }
  return hits;
}

// A pinhole camera's rays as 4×4 tiles (groups of 16), looking along `fwd`.
std::vector<Ray> camera_tiles(Vec3f eye, Vec3f fwd, Vec3f right, Vec3f up, int n, float half_width) {
  std::vector<Ray> rays;
  for (int ty = 0; ty < n; ty += 4)
    for (int tx = 0; tx < n; tx += 4)
      for (int k = 0; k < 16; ++k) {
        const float x = ((float(tx + k % 4) + 0.5f) / float(n) * 2.0f - 1.0f) * half_width;
        const float y = ((float(ty + k / 4) + 0.5f) / float(n) * 2.0f - 1.0f) * half_width;
        rays.push_back(Ray{eye, fwd + right * x + up * y});
      }
  return rays;
}

TEST_P(BvhWatertightPacket, HardCaseFamiliesMatchSingleRaysBitForBit) {
  int families = 0;
  for (const HardCaseFamily& f : hard_case_families(5, 1)) {
    const std::unique_ptr<BvhAccelerator> accel = bvh_unless_refused(f.mesh);
    if (!accel) continue;
    const int P = accel->traversal().packet_width;
    const int hits = expect_lanes_exact(*accel, test::four_copies(f.rays, P), f.name + " (four copies)");
    expect_lanes_exact(*accel, f.rays, f.name);
    if (f.crossing) {  // watertight: every crossing ray hits, in packets too
      std::size_t single = 0;
      for (const Ray& r : f.rays) single += accel->closest(r).hit();
      EXPECT_GT(single, f.rays.size() * 9 / 10) << f.name;
      EXPECT_EQ(std::size_t(hits), single * 4) << f.name;
    }
    ++families;
  }
  EXPECT_GE(families, 10);
}

TEST_P(BvhWatertightPacket, RandomRaysAndCamerasOfEveryPermutationMatchSingleRays) {
  const TriangleMesh soup = test::random_soup(3000, 0.15f, 41);
  const BvhAccelerator a = bvh(soup);
  const int P = a.traversal().packet_width;
  // random rays (axis-parallel with −0, per-lane tmin and tmax): packets mixing every permutation
  std::vector<Ray> rays = test::random_rays(1200, 1.5f, 42);
  EXPECT_GT(expect_lanes_exact(a, test::four_copies(rays, P), "random, four copies"), 500);
  expect_lanes_exact(a, rays, "random");
  // cameras along ±x, ±y, ±z (one permutation per packet), then wide ones whose tiles straddle the
  // diagonals where the dominant axis changes (several permutations in one packet)
  const Vec3f axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a_z = 0; a_z < 3; ++a_z)
    for (const float s : {1.0f, -1.0f})
      for (const float half : {0.6f, 2.5f}) {
        const Vec3f fwd = axes[a_z] * s, right = axes[(a_z + 1) % 3], up = axes[(a_z + 2) % 3];
        std::vector<Ray> cam =
            camera_tiles(fwd * -0.3f + Vec3f{0.03f, -0.02f, 0.01f}, fwd, right, up, 32, half);
        for (std::size_t i = 0; i < cam.size(); i += 5) cam[i].tmin = 0.5f;  // tmin mixed within packets
        const std::string what =
            "camera axis " + std::to_string(a_z) + (s > 0 ? "+" : "-") + " half " + std::to_string(half);
        EXPECT_GT(expect_lanes_exact(a, cam, what), 100) << what;
      }
  // from inside a closed sphere: every lane hits
  const TriangleMesh ball = test::sphere(1.0f, 24, 32);
  const BvhAccelerator b = bvh(ball);
  const std::vector<Ray> inside =
      camera_tiles({0.05f, 0.02f, 0.1f}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, 32, 3.0f);
  EXPECT_EQ(expect_lanes_exact(b, inside, "inside sphere"), int(inside.size()));
}

// Coherent packets through one shared edge each (16 points along it, from one interior origin) and
// through one shared vertex each (16 interior origins), on closed icospheres near the origin and far
// from it: every lane hits, and exactly as its single ray does.
TEST_P(BvhWatertightPacket, RaysThroughSharedEdgesAndVerticesOfAClosedMeshAllHit) {
  for (const Vec3d centre : {Vec3d{0.3, -0.2, 0.1}, Vec3d{148376, 1234, -223423}}) {
    const double radius = centre.x > 1000 ? 200.0 : 1.0;
    const TriangleMesh mesh = make_icosphere(centre, radius, 3, 77);
    const BvhAccelerator a = bvh(mesh);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    auto inner = [&] { return Vec3f(centre + Vec3d{u(rng), u(rng), u(rng)} * (0.3 * radius)); };
    std::vector<Ray> rays;
    for (std::size_t t = 0; t < mesh.size(); t += 3) {  // edges
      const Vec3d p = Vec3d(mesh.vertex(t, 0)), q = Vec3d(mesh.vertex(t, 1));
      const Vec3f org = inner();
      for (int k = 0; k < 16; ++k) {
        const Vec3d target = p + (q - p) * ((double(k) + 0.5) / 16.0);
        rays.push_back(Ray{org, Vec3f(target - Vec3d(org))});
      }
    }
    for (std::size_t v = 0; v < mesh.positions.size(); v += 2)  // vertices
      for (int k = 0; k < 16; ++k) {
        const Vec3f org = inner();
        rays.push_back(Ray{org, Vec3f(Vec3d(mesh.positions[v]) - Vec3d(org))});
      }
    EXPECT_EQ(expect_lanes_exact(a, rays, "centre.x " + std::to_string(centre.x)), int(rays.size()));
  }
}

// The single-ray kernel a spy table calls, counted.
std::atomic<long> g_single_calls{0};
const TriangleKernels* g_real = nullptr;
void counted_closest(const TriangleArrays& t, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  ++g_single_calls;
  g_real->closest(t, begin, end, ray, hit);
}

// The packet traversal with a table whose single-ray kernel counts its calls: with the `watertight`
// table no packet calls it (four copies a ray: no packet diverges into single rays), so the leaves ran
// the packet kernel; the same table labelled watertight64 or mt64 takes the per-lane fallback and calls
// it for every leaf, which shows the count works. Results equal single rays either way.
TEST_P(BvhWatertightPacket, PacketLeavesRunThePacketKernelNotTheSingleRayFallback) {
  const TriangleMesh ball = test::sphere(1.0f, 24, 32);
  const BvhAccelerator a = bvh(ball);
  const int P = a.traversal().packet_width;
  ASSERT_GT(P, 0);
  g_real = &triangle_kernels(GetParam().isa, Intersector::watertight);
  std::vector<Ray> inside = test::random_rays(400, 0.5f, 51);
  for (Ray& r : inside) r.tmax = kInf;  // every ray reaches the sphere
  const std::vector<Ray> rays = test::four_copies(inside, P);
  for (const Intersector label : {Intersector::watertight, Intersector::watertight64, Intersector::mt64}) {
    TriangleKernels spy = *g_real;
    spy.intersector = label;
    spy.closest = &counted_closest;
    g_single_calls = 0;
    std::vector<Hit> hits(rays.size());
    for (std::size_t i = 0; i < rays.size(); i += std::size_t(P))
      a.traversal().closest_packet(a.tree().arrays(), a.triangles().arrays(), spy, &rays[i], &hits[i],
                                   (1u << P) - 1u);
    int hit = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Hit want = a.closest(rays[i]);
      ASSERT_EQ(want.tri, hits[i].tri) << intersector_name(label) << " ray " << i;
      ASSERT_EQ(std::bit_cast<uint32_t>(want.t), std::bit_cast<uint32_t>(hits[i].t)) << "ray " << i;
      hit += hits[i].hit();
    }
    EXPECT_EQ(hit, int(rays.size())) << "from inside a closed sphere every ray hits";
    if (label == Intersector::watertight)
      EXPECT_EQ(g_single_calls.load(), 0) << "watertight packets called the single-ray kernel";
    else
      EXPECT_GE(g_single_calls.load(), long(rays.size())) << intersector_name(label) << " should fall back";
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsasWidths, BvhWatertightPacket,
                         ::testing::ValuesIn(test::bvh_cases({Intersector::watertight})),
                         test::bvh_case_name);

}  // namespace
}  // namespace rayvec
