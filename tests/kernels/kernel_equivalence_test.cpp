// ISA and version equivalence: every kernel version (original and optimized scalar baselines,
// vectorized per ISA) returns the same triangle ids, with the scalar ISA as the reference (as
// mitsuba tests every vector backend against its scalar one). ISAs this CPU lacks are skipped by name.
//
// `paper` has no FMA anywhere, so ids, t, u and v must match bit for bit — including the paper
// baselines. `mt` and `mt64` use FMA in the SIMD kernels but not in the scalar ISA, so a ray within
// rounding of an edge shared by two triangles may pick the neighbour: such an id mismatch is allowed
// only when both hits exist, their t agree within a few ulp (kUlps) and the hit lies within 1e-5
// (barycentric) of an edge; these cases are counted and must be rare on random rays. Rays aimed
// exactly at shared edges (the grid) may also slip through the crack on one side (`mt` is not
// watertight), again only within 1e-5 of an edge.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench/paper_scene.h"
#include "kernels/closest_batch.h"
#include "kernels/triangle_kernels.h"
#include "bench/paper_baselines.h"
#include "kernels/triangle_soa.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

struct Scene {
  const char* name;
  TriangleMesh mesh;
  std::vector<Ray> rays;
  bool edge_aimed = false;  // rays aimed exactly at shared edges: edge cases are not rare
};

Vec3f random_point(SplitMix64& rng, float lo, float hi) {
  return {lo + (hi - lo) * rng.unit_float(), lo + (hi - lo) * rng.unit_float(),
          lo + (hi - lo) * rng.unit_float()};
}

Vec3f random_direction(SplitMix64& rng) {
  for (;;) {
    const Vec3f d = random_point(rng, -1.0f, 1.0f);
    const float l2 = dot(d, d);
    if (l2 > 0.01f && l2 <= 1.0f) return d;
  }
}

// 400 random unit-cube triangles (plus a tiny and a degenerate one), random rays with some
// [tmin, tmax] windows.
Scene random_scene() {
  Scene s{"random", paper_triangles(400, 7), {}};
  s.mesh.add_triangle({0.3f, 0.3f, 0.3f}, {0.3001f, 0.3f, 0.3f}, {0.3f, 0.3001f, 0.3f});
  s.mesh.add_triangle({0.1f, 0.1f, 0.1f}, {0.2f, 0.2f, 0.2f}, {0.3f, 0.3f, 0.3f});
  SplitMix64 rng(11);
  for (int i = 0; i < 3000; ++i) {
    Ray r{random_point(rng, -0.5f, 1.5f), random_direction(rng)};
    if (i % 3 == 1) r.tmin = 0.2f * rng.unit_float();
    if (i % 3 == 2) r.tmax = 0.3f + rng.unit_float();
    s.rays.push_back(r);
  }
  const RayBatch camera = paper_camera_rays(30);
  for (std::size_t i = 0; i < camera.size(); ++i) s.rays.push_back(camera[i]);
  return s;
}

// A closed UV sphere (shared vertices, so every edge is shared by two triangles): rays from inside
// in random directions, and from outside towards random points inside.
Scene sphere_scene() {
  Scene s{"sphere", {}, {}};
  const int rings = 24, segments = 48;
  const float pi = 3.14159265358979f;
  s.mesh.positions.push_back({0, 0, 1});
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const float th = pi * r / rings, ph = 2 * pi * k / segments;
      s.mesh.positions.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  s.mesh.positions.push_back({0, 0, -1});
  const uint32_t south = uint32_t(s.mesh.positions.size() - 1);
  auto at = [&](int r, int k) { return uint32_t(1 + (r - 1) * segments + (k % segments)); };
  for (int k = 0; k < segments; ++k) s.mesh.triangles.push_back({0, at(1, k), at(1, k + 1)});
  for (int r = 1; r + 1 < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      s.mesh.triangles.push_back({at(r, k), at(r + 1, k), at(r + 1, k + 1)});
      s.mesh.triangles.push_back({at(r, k), at(r + 1, k + 1), at(r, k + 1)});
    }
  for (int k = 0; k < segments; ++k)
    s.mesh.triangles.push_back({at(rings - 1, k), south, at(rings - 1, k + 1)});
  SplitMix64 rng(23);
  for (int i = 0; i < 3000; ++i) {
    const Vec3f inside = random_point(rng, -0.5f, 0.5f);
    if (i % 2 == 0) {
      s.rays.push_back(Ray{inside, random_direction(rng)});
    } else {
      const Vec3f d = random_direction(rng);
      const Vec3f o = inside - d * (3.0f / length(d));
      s.rays.push_back(Ray{o, inside - o});
    }
  }
  return s;
}

// A 16×16 grid of quads (two triangles each) in the plane z = 0.5, rays from above aimed at points on
// grid lines and diagonals — the shared edges themselves.
Scene grid_scene() {
  Scene s{"grid", {}, {}, true};
  const int n = 16;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.mesh.positions.push_back({float(i) / n, float(j) / n, 0.5f});
  auto at = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  SplitMix64 rng(5);
  for (int k = 0; k < 2000; ++k) {
    const float a = float(1 + k % (n - 1)) / n, b = 0.05f + 0.9f * rng.unit_float();
    const Vec3f target =
        k % 3 == 0 ? Vec3f{a, b, 0.5f} : (k % 3 == 1 ? Vec3f{b, a, 0.5f} : Vec3f{b, b, 0.5f});
    const Vec3f o = random_point(rng, 0.0f, 1.0f) + Vec3f{0, 0, 1.0f};
    s.rays.push_back(Ray{o, target - o});
  }
  return s;
}

std::vector<Hit> trace(const TriangleKernels& k, const TriangleSoA& soa, const std::vector<Ray>& rays) {
  std::vector<Hit> hits(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) k.closest(soa.arrays(), 0, soa.size(), rays[i], hits[i]);
  return hits;
}

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

  void check(const Scene& s) {
    const Param p = GetParam();
    const TriangleSoA soa(s.mesh);
    const std::vector<Hit> ref = trace(triangle_kernels(Isa::scalar, p.intersector), soa, s.rays);
    const TriangleKernels& k = triangle_kernels(p.isa, p.intersector);
    const std::vector<Hit> got = trace(k, soa, s.rays);
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
  Scene s = random_scene();
  s.mesh = paper_triangles(2 * kTriangleChunk + 100, 3);
  s.rays.resize(401);  // odd; fewer than elsewhere: the triangle count follows the (L2-sized) chunk
  const TriangleSoA soa(s.mesh);
  const TriangleKernels& k = triangle_kernels(p.isa, p.intersector);
  const std::vector<Hit> one = trace(k, soa, s.rays);
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
    const std::vector<Hit> one = trace(k, soa, rays);
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

// Hard cases for the `mt` pre-tests: one triangle three times (ties across lanes and steps: the
// lowest id wins), degenerate ones, a triangle whose plane holds a ray, among random filler; rays
// at vertices and edges, with tmin or tmax exactly at a hit, in a plane, with NaN and zero parts.
Scene hard_scene() {
  Scene s{"hard", paper_triangles(60, 9), {}, true};
  const Vec3f a{0.2f, 0.2f, 2.0f}, b{0.8f, 0.2f, 2.0f}, c{0.2f, 0.8f, 2.0f};
  for (uint32_t at : {5u, 17u, 40u}) {
    const auto n = uint32_t(s.mesh.positions.size());
    s.mesh.triangles.insert(s.mesh.triangles.begin() + at, std::array<uint32_t, 3>{n, n + 1, n + 2});
    for (const Vec3f& p : {a, b, c}) s.mesh.positions.push_back(p);
  }
  s.mesh.add_triangle({0.4f, 0.4f, 1.0f}, {0.5f, 0.5f, 1.0f}, {0.6f, 0.6f, 1.0f});  // collinear
  s.mesh.add_triangle({0.3f, 0.3f, 1.5f}, {0.3f, 0.3f, 1.5f}, {0.3f, 0.3f, 1.5f});  // a point
  const float nan = std::nanf("");
  const Vec3f down{0, 0, 1};
  for (const Vec3f& target : {a, b, c, (a + b) * 0.5f, (b + c) * 0.5f, Vec3f{0.4f, 0.4f, 2.0f}}) {
    const Vec3f o = target - Vec3f{0.01f, 0.02f, 3.0f};
    s.rays.push_back(Ray{o, target - o});
    s.rays.push_back(Ray{o, target - o, 1.0f});        // tmin exactly at the hit
    s.rays.push_back(Ray{o, target - o, 0.0f, 1.0f});  // tmax exactly at the hit
    s.rays.push_back(Ray{o, target - o, 1.0f, 1.0f});  // both
  }
  s.rays.push_back(Ray{{0.0f, 0.5f, 2.0f}, {1, 0, 0}});  // in the duplicates' plane
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, down});       // through the collinear one and the point
  s.rays.push_back(Ray{{nan, 0.4f, 0.0f}, down});
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, {0, nan, 1}});
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, {0, 0, 0}});
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, down, nan});
  SplitMix64 rng(31);
  for (int i = 0; i < 500; ++i) s.rays.push_back(Ray{random_point(rng, -0.5f, 1.5f), random_direction(rng)});
  return s;
}

// The float `mt` kernels' two pre-tests (MtPretest) are conservative forms of the same conditions,
// so on every ISA they give the same hits bit for bit, one ray at a time and in batches (pairs).
TEST(MtPretest, BothFormsGiveTheSameHitsOnEveryIsa) {
  for (Isa isa : kAllIsas) {
    if (!isa_supported(isa)) {
      std::printf("[ skipped ] %s: this CPU lacks it\n", isa_name(isa));
      continue;
    }
    const TriangleKernels& sign = triangle_kernels(isa, Intersector::mt, MtPretest::sign_bits);
    const TriangleKernels& ordered = triangle_kernels(isa, Intersector::mt, MtPretest::ordered_compares);
    ASSERT_NE(sign.closest, ordered.closest) << isa_name(isa);
    for (const Scene& s : {random_scene(), sphere_scene(), grid_scene(), hard_scene()}) {
      const TriangleSoA soa(s.mesh);
      const std::vector<Hit> one = trace(sign, soa, s.rays), got = trace(ordered, soa, s.rays);
      std::vector<Hit> batch(s.rays.size());
      closest_batch(ordered, soa.arrays(), 0, soa.size(), s.rays.data(), batch.data(), batch.size());
      int hits = 0;
      for (std::size_t i = 0; i < s.rays.size(); ++i) {
        hits += one[i].hit();
        for (const Hit* h : {&got[i], static_cast<const Hit*>(&batch[i])}) {
          ASSERT_EQ(h->tri, one[i].tri) << isa_name(isa) << " " << s.name << " ray " << i;
          if (h->hit()) {
            ASSERT_EQ(h->t, one[i].t) << isa_name(isa) << " " << s.name << " ray " << i;
            ASSERT_EQ(h->u, one[i].u) << isa_name(isa) << " " << s.name << " ray " << i;
            ASSERT_EQ(h->v, one[i].v) << isa_name(isa) << " " << s.name << " ray " << i;
          }
        }
      }
      EXPECT_GT(hits * 20, int(s.rays.size())) << s.name;
    }
  }
}

TEST(MtPretest, OrderedComparesOnlyForIntelAvx512) {
  EXPECT_EQ(default_mt_pretest(Isa::avx512, "GenuineIntel"), MtPretest::ordered_compares);
  EXPECT_EQ(default_mt_pretest(Isa::avx512, "AuthenticAMD"), MtPretest::sign_bits);
  EXPECT_EQ(default_mt_pretest(Isa::avx2, "GenuineIntel"), MtPretest::sign_bits);
  EXPECT_EQ(default_mt_pretest(Isa::scalar, "GenuineIntel"), MtPretest::sign_bits);
  for (Isa isa : supported_isas())  // the two-argument table is the running CPU's default
    EXPECT_EQ(&triangle_kernels(isa, Intersector::mt),
              &triangle_kernels(isa, Intersector::mt, default_mt_pretest(isa, cpu_features().vendor)));
}

// The paper's scalar versions (Table 1's original and optimized) against the scalar `paper` kernel:
// the same arithmetic, so the same bits.
TEST(PaperBaselines, OriginalAndOptimizedMatchPaperKernelExactly) {
  for (const Scene& s : {random_scene(), sphere_scene(), grid_scene()}) {
    const TriangleSoA soa(s.mesh);
    const std::vector<Hit> ref = trace(triangle_kernels(Isa::scalar, Intersector::paper), soa, s.rays);
    RayBatch batch;
    for (const Ray& r : s.rays) batch.push_back(r);
    std::vector<Hit> original(s.rays.size()), optimized(s.rays.size());
    closest_original(paper_aos_triangles(s.mesh), s.rays, 0, s.rays.size(), original);
    closest_optimized(paper_soa_triangles(s.mesh), batch, 0, s.rays.size(), optimized);
    for (std::size_t i = 0; i < s.rays.size(); ++i) {
      for (const Hit* h : {&original[i], &optimized[i]}) {
        ASSERT_EQ(h->tri, ref[i].tri) << s.name << " ray " << i;
        if (h->hit()) {
          ASSERT_EQ(h->t, ref[i].t) << s.name << " ray " << i;
          ASSERT_EQ(h->u, ref[i].u) << s.name << " ray " << i;
          ASSERT_EQ(h->v, ref[i].v) << s.name << " ray " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace rayvec
