// ISA equivalence: every kernel vectorized per ISA returns the same triangle ids as the scalar ISA,
// the reference (as mitsuba tests every vector backend against its scalar one); and every batched
// path (closest_batch, occluded_batch, the groups of rays from one origin, stored or formed normals)
// the same hits, bit for bit, as one call per ray on the same ISA. ISAs this CPU lacks are skipped
// by name. The scenes: kernel_scenes.h.
//
// `paper` has no FMA anywhere, so ids, t, u and v must match bit for bit. `mt` and `mt64` use FMA in the SIMD
// kernels but not in the scalar ISA, so a ray within rounding of an edge shared by two triangles may pick the
// neighbour: such an id mismatch is allowed only when both hits exist, their t agree within a few ulp (kUlps)
// and the hit lies within 1e-5 (barycentric) of an edge; these cases are counted and must be rare on random
// rays. Rays aimed exactly at shared edges (the grid) may also slip through the crack on one side (`mt` is
// not watertight), again only within 1e-5 of an edge.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "bench/paper_scene.h"
#include "kernels/closest_batch.h"
#include "kernels/kernel_scenes.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

using test::closest_one_by_one;
using test::grid_scene;
using test::KernelScene;
using test::random_scene;
using test::sphere_scene;

bool near_edge(const Hit& h) {
  const float w = 1.0f - h.u - h.v;
  return std::fmin(std::fmin(h.u, h.v), w) < 1e-5f;
}

// FMA against separately rounded products in the triple products of t = (e2 · q) / det: a few ulp
// after cancellation (6 seen on the sphere), so 16. The rounding error scales with the scene (unit
// size here), not with t, so a t much smaller than 1 is compared in ulps of 1.
constexpr int kUlps = 16;

// t agree within `ulps` units in the last place of max(|a|, |b|, 1).
bool close_t(float a, float b, int ulps) {
  const float scale = std::fmax(std::fmax(std::fabs(a), std::fabs(b)), 1.0f);
  return std::fabs(a - b) <= ulps * (std::nextafter(scale, INFINITY) - scale);
}

struct Param {
  Isa isa;
  Intersector intersector;
};

// The tables of p: for `mt` both pre-test forms (each CPU's default runs only one; the group kernels
// take a different path for each), else the one table.
std::vector<const TriangleKernels*> tables_of(const Param& p) {
  if (p.intersector != Intersector::mt) return {&triangle_kernels(p.isa, p.intersector)};
  return {&triangle_kernels(p.isa, p.intersector, MtPretest::sign_bits),
          &triangle_kernels(p.isa, p.intersector, MtPretest::ordered_compares)};
}

class KernelEquivalence : public ::testing::TestWithParam<Param> {
 protected:
  void SetUp() override {
    if (!isa_supported(GetParam().isa))
      GTEST_SKIP() << "CPU lacks " << isa_name(GetParam().isa) << ": skipped";
  }

  void check(const KernelScene& s) {
    const Param p = GetParam();
    const TriangleSoA soa(s.mesh);
    const std::vector<Hit> ref =
        closest_one_by_one(triangle_kernels(Isa::scalar, p.intersector), soa, s.rays);
    const TriangleKernels& k = triangle_kernels(p.isa, p.intersector);
    const std::vector<Hit> got = closest_one_by_one(k, soa, s.rays);
    const bool exact = p.intersector == Intersector::paper;
    int edge_cases = 0, hits = 0;
    for (std::size_t i = 0; i < s.rays.size(); ++i) {
      const Hit &a = ref[i], &b = got[i];
      hits += a.hit();
      // any-hit agrees with closest hit of the same kernels
      EXPECT_EQ(k.occluded(soa.arrays(), 0, soa.size(), s.rays[i], nullptr), b.hit())
          << s.name << " ray " << i;
      if (exact) {
        ASSERT_EQ(a.tri, b.tri) << s.name << " ray " << i;
        if (a.hit()) {
          ASSERT_EQ(a.t, b.t) << s.name << " ray " << i;
          ASSERT_EQ(a.u, b.u) << s.name << " ray " << i;
          ASSERT_EQ(a.v, b.v) << s.name << " ray " << i;
        }
        continue;
      }
      if (a.tri == b.tri) {
        if (a.hit()) {
          EXPECT_TRUE(close_t(a.t, b.t, kUlps)) << s.name << " ray " << i << ": t " << a.t << " vs " << b.t;
          EXPECT_NEAR(a.u, b.u, 1e-4f) << s.name << " ray " << i;
          EXPECT_NEAR(a.v, b.v, 1e-4f) << s.name << " ray " << i;
        }
        continue;
      }
      ++edge_cases;
      if (!a.hit() || !b.hit()) {  // slipped through a crack: only for rays aimed at edges
        ASSERT_TRUE(s.edge_aimed) << s.name << " ray " << i << ": hit " << a.tri << " vs " << b.tri;
        EXPECT_TRUE(near_edge(a.hit() ? a : b)) << s.name << " ray " << i << ": miss away from an edge";
        continue;
      }
      EXPECT_TRUE(close_t(a.t, b.t, kUlps)) << s.name << " ray " << i << ": t " << a.t << " vs " << b.t;
      EXPECT_TRUE(near_edge(a) && near_edge(b))
          << s.name << " ray " << i << ": ids " << a.tri << " vs " << b.tri << " away from any edge";
    }
    EXPECT_GT(hits, int(s.rays.size() / 10)) << s.name << ": the scene should be hit";
    if (!s.edge_aimed) {
      EXPECT_LE(edge_cases * 200, int(s.rays.size())) << s.name << ": too many edge cases";
    }
    std::printf("[ %s ] %s/%s: %d of %zu rays hit a shared edge and picked the neighbour\n", s.name,
                isa_name(p.isa), intersector_name(p.intersector), edge_cases, s.rays.size());
  }
};

// closest_batch (triangle chunks, several rays per step where the table has closest_group) returns exactly
// what one closest call per ray returns, on the same ISA: more triangles than one chunk, an odd ray
// count, rays with tmin > 0 mixed in, and a batch resumed from earlier hits.
TEST_P(KernelEquivalence, BatchMatchesOneRayAtATime) {
  const Param p = GetParam();
  KernelScene s = random_scene();
  s.mesh = paper_triangles(2 * kTriangleChunk + 100, 3);
  s.rays.resize(401);  // odd; fewer than elsewhere: the triangle count follows the (L2-sized) chunk
  const TriangleSoA soa(s.mesh);
  const TriangleKernels& k = triangle_kernels(p.isa, p.intersector);
  const std::vector<Hit> one = closest_one_by_one(k, soa, s.rays);
  std::vector<Hit> batch(s.rays.size());
  closest_batch(k, soa.arrays(), 0, soa.size(), s.rays.data(), batch.data(), batch.size());
  // resumed: the first half of the triangles, then the rest on top of those hits
  std::vector<Hit> resumed(s.rays.size());
  const uint32_t half = soa.size() / 2 + 5;
  closest_batch(k, soa.arrays(), 0, half, s.rays.data(), resumed.data(), resumed.size());
  closest_batch(k, soa.arrays(), half, soa.size(), s.rays.data(), resumed.data(), resumed.size());
  int hits = 0;
  for (std::size_t i = 0; i < s.rays.size(); ++i) {
    hits += one[i].hit();
    for (const Hit* h : {&batch[i], &resumed[i]}) {
      ASSERT_EQ(h->tri, one[i].tri) << "ray " << i;
      if (h->hit()) {
        ASSERT_EQ(h->t, one[i].t) << "ray " << i;
        ASSERT_EQ(h->u, one[i].u) << "ray " << i;
        ASSERT_EQ(h->v, one[i].v) << "ray " << i;
      }
    }
  }
  EXPECT_GT(hits * 10, int(s.rays.size()));  // enough hits (about 19 %) to compare
}

// Rays from one origin (a camera's) share part of each step's arithmetic in the group kernels (8,
// 4 or 2 rays); the hits must still be bit for bit those of one ray at a time: camera rays over more
// than one chunk, in the second half some with tmin > 0 or a finite tmax (groups that mix them), and
// pairs whose origins differ only in the sign of a zero (taken as two origins); `mt` with both
// pre-test tables (a group tests a step once with the sign bits, each ray with the ordered form).
TEST_P(KernelEquivalence, BatchFromOneOriginMatchesOneRayAtATime) {
  const Param p = GetParam();
  TriangleMesh mesh = paper_triangles(kTriangleChunk + 300, 5);
  for (int k = 0; k < 3; ++k)  // the same triangle three times: equal t in different lanes and steps
    mesh.add_triangle({0.2f, 0.2f, 0.5f}, {0.8f, 0.2f, 0.5f}, {0.2f, 0.8f, 0.5f});
  const RayBatch camera = paper_camera_rays(24);
  std::vector<Ray> rays;
  for (std::size_t i = 0; i < camera.size(); ++i) {
    Ray r = camera[i];
    if (i >= camera.size() / 2 && i % 8 == 2) r.tmin = 0.25f;
    if (i >= camera.size() / 2 && i % 8 == 5) r.tmax = 1.0f;
    rays.push_back(r);
  }
  for (int k = 0; k < 40; ++k) {  // origins (±0, 0.5, −1): a pair of each sign, then mixed pairs
    const float x = (k / 2) % 2 == 0 ? 0.0f : -0.0f;
    const float y = k < 20 ? x : (k % 2 == 0 ? 0.0f : -0.0f);
    rays.push_back(Ray{{y, 0.5f, -1.0f}, {0.02f * float(k % 7) + 0.05f, -0.01f * float(k % 5), 1.0f}});
    rays.push_back(Ray{{x, 0.5f, -1.0f}, {0.03f * float(k % 5) + 0.05f, 0.01f * float(k % 3), 1.0f}});
  }
  const TriangleSoA soa(mesh);
  for (const TriangleKernels* table : tables_of(p)) {
    const TriangleKernels& k = *table;
    const std::vector<Hit> one = closest_one_by_one(k, soa, rays);
    std::vector<Hit> batch(rays.size());
    closest_batch(k, soa.arrays(), 0, soa.size(), rays.data(), batch.data(), batch.size());
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      hits += one[i].hit();
      ASSERT_EQ(batch[i].tri, one[i].tri) << "ray " << i;
      if (batch[i].hit()) {
        ASSERT_EQ(batch[i].t, one[i].t) << "ray " << i;
        ASSERT_EQ(batch[i].u, one[i].u) << "ray " << i;
        ASSERT_EQ(batch[i].v, one[i].v) << "ray " << i;
      }
    }
    EXPECT_GT(hits * 4, int(rays.size()));
  }
}

// Ignores one triangle id (the ray's nearest hit, or none: −2).
bool ignore_id(const void* context, int32_t tri) { return tri == *static_cast<const int32_t*>(context); }

// occluded_batch with rays from one origin (the any-hit groups) answers as one `occluded` call per
// ray, each with its own filter: camera rays over more than one chunk, each ray's tmax at its nearest
// hit, so only that triangle (or a tie) can occlude, and every other ray's filter ignoring it — a
// filter given to the wrong ray of a group changes the answer; `mt` with both pre-test tables.
TEST_P(KernelEquivalence, OccludedBatchFromOneOriginMatchesOneRayAtATime) {
  const Param p = GetParam();
  const TriangleSoA soa(paper_triangles(kTriangleChunk + 300, 5));
  for (const TriangleKernels* table : tables_of(p)) {
    const TriangleKernels& k = *table;
    const RayBatch camera = paper_camera_rays(24);
    std::vector<Ray> rays;
    std::vector<int32_t> ignored;
    for (std::size_t i = 0; i < camera.size(); ++i) {
      Ray r = camera[i];
      Hit h;
      k.closest(soa.arrays(), 0, soa.size(), r, h);
      if (h.hit() && i % 3 != 2) r.tmax = h.t;
      rays.push_back(r);
      ignored.push_back(h.hit() && i % 2 == 1 ? h.tri : -2);
    }
    std::vector<HitFilter> filters(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) filters[i] = {&ignore_id, &ignored[i]};
    std::vector<uint8_t> batch(rays.size());
    occluded_batch(k, soa.arrays(), 0, soa.size(), rays.data(), batch.data(), batch.size(), filters.data());
    int occluded = 0, freed = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const bool want = k.occluded(soa.arrays(), 0, soa.size(), rays[i], &filters[i]);
      ASSERT_EQ(batch[i], want ? 1 : 0) << "ray " << i;
      occluded += want;
      freed += !want && ignored[i] >= 0;
    }
    EXPECT_GT(occluded * 4, int(rays.size()));
    EXPECT_GT(freed * 8, int(rays.size())) << "the filters should clear some rays";
  }
}

// The float `mt` kernels read stored normals or form them per step from the edges
// (TriangleSoA's Normals): bit for bit the same hits, for one ray, pairs and groups from one origin
// (closest_batch), and any-hit alone and in groups; the other intersectors never read them.
TEST_P(KernelEquivalence, StoredAndFormedNormalsGiveTheSameHits) {
  const Param p = GetParam();
  const TriangleKernels& k = triangle_kernels(p.isa, p.intersector);
  const TriangleMesh triangles = paper_triangles(kTriangleChunk + 300, 7);
  const TriangleSoA stored(triangles, {}, Normals::stored), formed(triangles, {}, Normals::formed);
  ASSERT_TRUE(stored.stores_normals());
  ASSERT_FALSE(formed.stores_normals());
  EXPECT_EQ(stored.bytes(), formed.bytes() + stored.padded_size() * TriangleSoA::kNormalBytes);
  std::vector<Ray> rays;
  const RayBatch camera = paper_camera_rays(16);  // from one origin: the group kernels
  for (std::size_t i = 0; i < camera.size(); ++i) rays.push_back(camera[i]);
  for (const Ray& r : random_scene().rays) rays.push_back(r);  // from many: pairs
  std::vector<Hit> a(rays.size()), b(rays.size());
  closest_batch(k, stored.arrays(), 0, stored.size(), rays.data(), a.data(), a.size());
  closest_batch(k, formed.arrays(), 0, formed.size(), rays.data(), b.data(), b.size());
  std::vector<uint8_t> oa(rays.size()), ob(rays.size());
  occluded_batch(k, stored.arrays(), 0, stored.size(), rays.data(), oa.data(), oa.size(), nullptr);
  occluded_batch(k, formed.arrays(), 0, formed.size(), rays.data(), ob.data(), ob.size(), nullptr);
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit one_stored, one_formed;
    k.closest(stored.arrays(), 7, stored.size(), rays[i], one_stored);  // a head step too
    k.closest(formed.arrays(), 7, formed.size(), rays[i], one_formed);
    for (const auto& [x, y] : {std::pair{a[i], b[i]}, std::pair{one_stored, one_formed}}) {
      ASSERT_EQ(x.tri, y.tri) << "ray " << i;
      ASSERT_TRUE(!x.hit() || (x.t == y.t && x.u == y.u && x.v == y.v)) << "ray " << i;
    }
    ASSERT_EQ(oa[i], ob[i]) << "ray " << i;
    ASSERT_EQ(k.occluded(stored.arrays(), 3, stored.size(), rays[i], nullptr),
              k.occluded(formed.arrays(), 3, formed.size(), rays[i], nullptr))
        << "ray " << i;
    hits += a[i].hit();
  }
  EXPECT_GT(hits * 10, int(rays.size()));
}

TEST_P(KernelEquivalence, RandomTrianglesMatchScalar) { check(random_scene()); }
TEST_P(KernelEquivalence, ClosedSphereMatchesScalar) { check(sphere_scene()); }
TEST_P(KernelEquivalence, EdgeAimedGridMatchesScalar) { check(grid_scene()); }

std::vector<Param> all_params() {
  std::vector<Param> out;
  for (Isa isa : kAllIsas)
    for (Intersector in : kAllIntersectors) out.push_back({isa, in});
  return out;
}

INSTANTIATE_TEST_SUITE_P(AllIsas, KernelEquivalence, ::testing::ValuesIn(all_params()),
                         [](const ::testing::TestParamInfo<Param>& info) {
                           return std::string(isa_name(info.param.isa)) + "_" +
                                  intersector_name(info.param.intersector);
                         });

}  // namespace
}  // namespace rayvec
