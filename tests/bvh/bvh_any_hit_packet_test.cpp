// Any-hit packets (bvh/packet_any_hit.inl, BvhAccelerator::occluded_stream): every lane of a packet
// must get exactly the single-ray answer occluded(ray, filter) — on the hard-case families with tmax
// set exactly at and just before each ray's nearest hit (the closed end t <= tmax), on random rays
// with mixed tmin and tmax, on shadow rays of camera tiles toward a point light, and on segments from
// one origin to each vertex of a closed mesh with a filter per ray (the visibility workload) — for
// every ISA with packets, intersector and node width. The packets run the packet kernel for float
// `mt` and `watertight`, the table's single-ray kernel for the others, and occluded_stream sends
// only groups of aligned directions as packets. ISAs the CPU lacks are skipped and named.
#include <gtest/gtest.h>

#include <atomic>
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

using BvhAnyHitPacket = test::BvhPacketCaseTest;

// Every group of P rays as one packet (the traversal's occluded_packet, coherent or not), and the
// whole list through occluded_stream, against occluded() ray by ray. Returns the occluded count.
int expect_same_occlusion(const BvhAccelerator& a, const std::vector<Ray>& rays,
                          const std::vector<HitFilter>* filters, const std::string& what) {
  const std::size_t P = std::size_t(a.traversal().packet_width);
  std::vector<uint8_t> stream(rays.size());
  a.occluded_stream(rays.data(), stream.data(), rays.size(), filters ? filters->data() : nullptr);
  int occluded = 0, wrong = 0;
  for (std::size_t i = 0; i < rays.size(); i += P) {
    const std::size_t n = std::min(P, rays.size() - i);
    const TriangleKernels& kernels = triangle_kernels(a.config().isa, a.config().intersector);
    const HitFilter* f = filters ? &(*filters)[i] : nullptr;
    const unsigned packet = a.traversal().occluded_packet(a.tree().arrays(), a.triangles().arrays(), kernels,
                                                          &rays[i], (1u << n) - 1u, f, i / P % 2 == 1);
    const unsigned other = a.traversal().occluded_packet(a.tree().arrays(), a.triangles().arrays(), kernels,
                                                         &rays[i], (1u << n) - 1u, f, i / P % 2 == 0);
    EXPECT_EQ(packet, other) << what << " packet at " << i << ": children in node order and front to back";
    for (std::size_t k = 0; k < n; ++k) {
      const bool want = a.occluded(rays[i + k], filters ? &(*filters)[i + k] : nullptr);
      const bool same = want == bool((packet >> k) & 1u) && want == bool(stream[i + k]);
      if (!same && ++wrong <= 3)
        ADD_FAILURE() << what << " ray " << i + k << ": single ray " << want << ", packet "
                      << ((packet >> k) & 1u) << ", occluded_stream " << int(stream[i + k]);
      occluded += want;
    }
  }
  EXPECT_EQ(wrong, 0) << what << ": lanes unlike their single ray";
  return occluded;
}

TEST_P(BvhAnyHitPacket, HardCaseFamiliesMatchSingleRaysAtTheClosedEnd) {
  int families = 0, at_hit = 0;
  for (const HardCaseFamily& f : hard_case_families(5, 1)) {
    const std::unique_ptr<BvhAccelerator> accel = bvh_unless_refused(f.mesh);
    if (!accel) continue;
    // each ray, then with tmax at its nearest hit (occluded: t <= tmax) and just before it
    std::vector<Ray> rays;
    for (const Ray& r : f.rays) {
      rays.push_back(r);
      const Hit h = accel->closest(r);
      if (!h.hit()) continue;
      Ray at = r, before = r;
      at.tmax = h.t;
      before.tmax = std::nextafter(h.t, -kInf);
      rays.push_back(at);
      rays.push_back(before);
      at_hit += accel->occluded(at);
    }
    expect_same_occlusion(*accel, rays, nullptr, f.name);
    expect_same_occlusion(*accel, test::four_copies(rays, accel->traversal().packet_width), nullptr,
                          f.name + " (four copies)");
    ++families;
  }
  EXPECT_GE(families, 10);
  EXPECT_GT(at_hit, 100) << "rays whose tmax is their hit's t are occluded";
}

TEST_P(BvhAnyHitPacket, RandomRaysAndShadowTilesMatchSingleRays) {
  const TriangleMesh soup = test::random_soup(3000, 0.15f, 41);
  const BvhAccelerator a = bvh(soup);
  const int P = a.traversal().packet_width;
  const std::vector<Ray> rays = test::random_rays(1200, 1.5f, 42);
  EXPECT_GT(expect_same_occlusion(a, rays, nullptr, "random"), 100);
  EXPECT_GT(expect_same_occlusion(a, test::four_copies(rays, P), nullptr, "random, four copies"), 400);
  // shadow rays: from the hits of camera tiles toward a point light, as the renderer forms them
  const Vec3f light{0.4f, 2.5f, 1.8f};
  std::vector<Ray> shadow;
  for (int ty = 0; ty < 64; ty += 4)
    for (int tx = 0; tx < 64; tx += 4)
      for (int k = 0; k < 16; ++k) {
        const Vec3f eye{0.1f, 0.2f, 3.0f};
        const Vec3f d{(float(tx + k % 4) + 0.5f) / 64 - 0.5f, (float(ty + k / 4) + 0.5f) / 64 - 0.5f, -1.0f};
        const Hit h = a.closest(Ray{eye, d});
        const Vec3f p = h.hit() ? eye + d * h.t : eye + d;
        shadow.push_back(Ray{p, light - p, 1e-4f, 0.99999f});
      }
  const int blocked = expect_same_occlusion(a, shadow, nullptr, "shadow tiles");
  EXPECT_GT(blocked, 100);
  EXPECT_LT(blocked, int(shadow.size()));
}

// The visibility workload's filter: a segment ending at a vertex ignores the triangles touching it.
struct TouchingVertex {
  const TriangleMesh* mesh;
  uint32_t vertex;
};
bool ignore_touching(const void* context, int32_t id) {
  const auto* c = static_cast<const TouchingVertex*>(context);
  for (uint32_t v : c->mesh->triangles[std::size_t(id)])
    if (v == c->vertex) return true;
  return false;
}

TEST_P(BvhAnyHitPacket, SegmentsToEveryVertexWithAFilterPerRayMatchSingleRays) {
  for (const Vec3d centre : {Vec3d{0.3, -0.2, 0.1}, Vec3d{148376, 1234, -223423}}) {
    const double radius = centre.x > 1000 ? 200.0 : 1.0;
    const TriangleMesh mesh = make_icosphere(centre, radius, 3, 77);
    const BvhAccelerator a = bvh(mesh);
    const Vec3f origin(centre + Vec3d{0.2, 0.1, -3.0} * radius);
    std::vector<TouchingVertex> contexts(mesh.positions.size());
    std::vector<HitFilter> filters(mesh.positions.size());
    std::vector<Ray> rays;
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
      contexts[v] = {&mesh, v};
      filters[v] = {&ignore_touching, &contexts[v]};
      rays.push_back(Ray{origin, mesh.positions[v] - origin, 0.0f, 1.0f});
    }
    const std::string what = "centre.x " + std::to_string(centre.x);
    const int hidden = expect_same_occlusion(a, rays, &filters, what);
    // a convex closed mesh seen from outside: about half its vertices lie behind it
    EXPECT_GT(hidden, int(rays.size()) / 4) << what;
    EXPECT_LT(hidden, int(rays.size()) * 3 / 4) << what;
    EXPECT_GT(expect_same_occlusion(a, rays, nullptr, what + " unfiltered"), hidden)
        << "unfiltered, segments also hit their own vertex's triangles at t = 1";
  }
}

// The single-ray any-hit kernel a spy table calls, counted.
std::atomic<long> g_single_calls{0};
const TriangleKernels* g_real = nullptr;
bool counted_occluded(const TriangleArrays& t, uint32_t begin, uint32_t end, const Ray& ray,
                      const HitFilter* filter) {
  ++g_single_calls;
  return g_real->occluded(t, begin, end, ray, filter);
}

// Packets of P copies of one ray each (no lane leaves the others before a hit) with a table whose
// single-ray any-hit kernel counts its calls: float `mt` and `watertight` leaves run the packet
// kernel and never call it; the same table labelled mt64 takes the per-lane fallback, which shows
// the count works. Results equal single rays either way.
TEST_P(BvhAnyHitPacket, FullPacketsRunThePacketKernelNotTheSingleRayFallback) {
  const TriangleMesh ball = test::sphere(1.0f, 24, 32);
  const BvhAccelerator a = bvh(ball);
  const int P = a.traversal().packet_width;
  ASSERT_GT(P, 0);
  g_real = &triangle_kernels(a.config().isa, a.config().intersector);
  std::vector<Ray> rays;
  for (const Ray& r : test::random_rays(200, 0.5f, 51))
    for (int k = 0; k < P; ++k) rays.push_back(Ray{r.org, r.dir, 0.0f, kInf});  // inside: every ray hits
  const Intersector own = GetParam().intersector;
  const bool packet_kernel = own == Intersector::mt || own == Intersector::watertight;
  for (const Intersector label : {own, Intersector::mt64}) {
    TriangleKernels spy = *g_real;
    spy.intersector = label;
    spy.occluded = &counted_occluded;
    g_single_calls = 0;
    int occluded = 0;
    for (std::size_t i = 0; i < rays.size(); i += std::size_t(P))
      occluded += __builtin_popcount(a.traversal().occluded_packet(a.tree().arrays(), a.triangles().arrays(),
                                                                   spy, &rays[i], (1u << P) - 1u, nullptr,
                                                                   i / std::size_t(P) % 2 == 0));
    EXPECT_EQ(occluded, int(rays.size())) << "from inside a closed sphere every ray is occluded";
    if (label == own && packet_kernel)
      EXPECT_EQ(g_single_calls.load(), 0)
          << intersector_name(label) << " packets called the single-ray kernel";
    else
      EXPECT_GE(g_single_calls.load(), long(rays.size() / std::size_t(P))) << intersector_name(label);
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsasIntersectorsWidths, BvhAnyHitPacket,
                         ::testing::ValuesIn(test::bvh_cases({Intersector::mt, Intersector::watertight,
                                                              Intersector::mt64, Intersector::paper,
                                                              Intersector::watertight64})),
                         test::bvh_case_name);

// occluded_stream takes packets only for groups whose directions lie within kPacketCone.
TEST(PacketAligned, AcceptsNearlyParallelRaysFromAnyOriginsOnly) {
  std::vector<Ray> rays;
  for (int k = 0; k < 16; ++k)  // toward one far point from nearby origins (shadow rays)
    rays.push_back(Ray{{0.01f * float(k), 0.02f * float(k % 4), 0.0f}, Vec3f{0.0f, 10.0f, 3.0f}});
  EXPECT_TRUE(packet_aligned(rays.data(), rays.size()));
  EXPECT_FALSE(packet_coherent(rays.data(), rays.size())) << "origins differ";
  rays[7].dir = {1.0f, 0.0f, 0.0f};  // 73 degrees off
  EXPECT_FALSE(packet_aligned(rays.data(), rays.size()));
  rays[7].dir = {0.0f, NAN, 3.0f};
  EXPECT_FALSE(packet_aligned(rays.data(), rays.size()));
}

}  // namespace
}  // namespace rayvec
