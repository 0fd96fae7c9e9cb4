// The BVH must return exactly what brute force returns (same ids, t, u, v; equal t: lowest id) for
// closest and any-hit queries, on every ISA this CPU has, every intersector and every node width.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "accel/brute_force.h"
#include "accuracy/hard_cases.h"
#include "accel/bvh_accelerator.h"
#include "bvh/bvh_traversal.h"
#include "bvh_cases.h"
#include "bvh_scenes.h"
#include "wide_leaves.h"

namespace rayvec {
namespace {

using Case = test::BvhCase;

class BvhTraversal : public test::BvhCaseTest {
 protected:
  // The double kernels order hits by their unrounded t inside one call but only see the float t of
  // an earlier result (Hit::t), so two hits whose t rounds to the same float may be resolved
  // differently by one brute-force call and by several leaf calls: accept either id then.
  bool rounded_t_ties() const {
    return GetParam().intersector == Intersector::mt64 || GetParam().intersector == Intersector::watertight64;
  }

  // The options of expect_same's BvhAccelerator: this case's width, leaf_call_, merge_steps_ and,
  // when given, leaves from `sah` instead of the kernel's width.
  BvhOptions options(std::optional<SahConfig> sah = std::nullopt) const {
    BvhOptions o;
    if (sah) {
      o.sah = *sah;
      o.leaves_from_kernel = false;
    }
    o.width = GetParam().width;
    o.leaf_call = leaf_call_;
    o.merge_steps = merge_steps_;
    o.stored_normals = stored_normals_;
    return o;
  }

  // Every ray through both accelerators; any-hit also with a filter ignoring even ids.
  void expect_same(const TriangleMesh& mesh, const std::vector<Ray>& rays,
                   std::optional<SahConfig> sah = std::nullopt) {
    const BruteForce brute(mesh, config());
    const BvhAccelerator bvh(mesh, config(), options(sah));
    const HitFilter odd_only{[](const void*, int32_t id) { return id % 2 == 0; }, nullptr};
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Hit a = brute.closest(rays[i]), b = bvh.closest(rays[i]);
      if (rounded_t_ties() && a.tri >= 0 && b.tri >= 0 && a.t == b.t) {
        ++hits;
        continue;
      }
      ASSERT_EQ(a.tri, b.tri) << "ray " << i << " t " << a.t << " vs " << b.t;
      if (a.tri >= 0) {
        ++hits;
        ASSERT_EQ(a.t, b.t) << "ray " << i;
        ASSERT_EQ(a.u, b.u) << "ray " << i;
        ASSERT_EQ(a.v, b.v) << "ray " << i;
      }
      ASSERT_EQ(brute.occluded(rays[i]), bvh.occluded(rays[i])) << "ray " << i;
      ASSERT_EQ(brute.occluded(rays[i], &odd_only), bvh.occluded(rays[i], &odd_only)) << "ray " << i;
    }
    if (mesh.size() > 0 && rays.size() > 100) {
      EXPECT_GT(hits, 0) << "the scene tests nothing";
    }
  }

  int leaf_call_ = -1;                                // BvhOptions::leaf_call of expect_same's BvhAccelerator
  int merge_steps_ = BvhOptions{}.merge_steps;        // and its merge_steps
  int stored_normals_ = BvhOptions{}.stored_normals;  // and its stored_normals
};

TEST_P(BvhTraversal, ClosestAndAnyHitMatchBruteForceOnRandomSoups) {
  expect_same(test::random_soup(2000, 0.1f, 1), test::random_rays(1500, 1.5f, 2));
  expect_same(test::random_soup(500, 0.6f, 3), test::random_rays(1000, 1.2f, 4));
}

// Spatial splits (bvh/spatial_split.h) reference the long triangles in several leaves, each leaf's
// box bounding only their part in it: the hits stay brute force's, ties and any-hit included.
TEST_P(BvhTraversal, ClosestAndAnyHitMatchBruteForceWithSpatialSplits) {
  TriangleMesh mesh = test::long_slivers(3000, 31);
  const float nan = std::nanf(""), inf = kInf;  // never hit; binned and partitioned all the same
  mesh.add_triangle({nan, nan, nan}, {nan, nan, nan}, {nan, nan, nan});
  mesh.add_triangle({-0.5f, 0.2f, 0.0f}, {nan, 0.1f, 0.0f}, {0.9f, 0.5f, -0.3f});
  const BvhAccelerator bvh(mesh, config(), options());
  std::size_t references = 0;
  for (std::size_t s = 0; s < bvh.triangles().size(); ++s) references += bvh.triangles().id(s) >= 0 ? 1 : 0;
  EXPECT_GT(references, mesh.size() + mesh.size() / 20) << "few triangles in two leaves: nothing new tested";
  std::vector<Ray> rays = test::random_rays(2000, 1.5f, 32);
  for (std::size_t i = 0; i < rays.size(); i += 4)
    rays[i].dir = Vec3f{0.01f, -1.0f, 0.02f};  // onto the floor
  expect_same(mesh, rays);
  // an infinite vertex makes the root's box infinite: no spatial split then, the same hits
  mesh.add_triangle({-0.5f, 0.0f, 0.0f}, {inf, 0.1f, 0.0f}, {0.0f, 0.5f, 0.0f});
  mesh.add_triangle({-inf, -inf, -inf}, {inf, inf, inf}, {0.0f, 0.0f, 0.0f});
  expect_same(mesh, rays);
}

// The float `mt` kernels read the normals from the triangle rows or form them per step: the same
// hits either way, single rays and packets (closest_stream). By default a mesh of long slivers, whose
// spatial-split references with stored normals would pass kBvhBytesPerTriangle, gets formed ones
// (and then fits, with the float kernels of the SIMD ISAs), an even mesh stored ones; no other
// intersector stores them.
TEST_P(BvhTraversal, StoredAndFormedNormalsMatchBruteForce) {
  const TriangleMesh soup = test::random_soup(2500, 0.1f, 42), slivers = test::long_slivers(3000, 31);
  const std::vector<Ray> rays = test::random_rays(1500, 1.5f, 43);
  const BruteForce brute(slivers, config());
  for (const int stored : {0, 1}) {
    stored_normals_ = stored;
    expect_same(soup, rays);
    expect_same(slivers, rays);
    const BvhAccelerator bvh(slivers, config(), options());
    EXPECT_EQ(bvh.triangles().stores_normals(), stored == 1 && GetParam().intersector == Intersector::mt);
    std::vector<Ray> tiles;  // 4×4 camera tiles toward the slivers' floor, for the packet leaves
    for (int t = 0; t < 64; ++t)
      for (int k = 0; k < 16; ++k)
        tiles.push_back(Ray{{0.0f, 1.5f, -2.0f},
                            {0.04f * float(t % 8 - 4) + 0.01f * float(k % 4),
                             -0.6f + 0.03f * float(t / 8) + 0.008f * float(k / 4), 1.0f}});
    std::vector<Hit> hits(tiles.size());
    bvh.closest_stream(tiles.data(), hits.data(), hits.size());
    int hit = 0;
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      const Hit want = brute.closest(tiles[i]);
      hit += want.hit();
      ASSERT_EQ(hits[i].tri, want.tri) << "stored " << stored << " ray " << i;
      if (want.hit()) {
        ASSERT_EQ(hits[i].t, want.t) << "stored " << stored << " ray " << i;
        ASSERT_EQ(hits[i].u, want.u) << "stored " << stored << " ray " << i;
        ASSERT_EQ(hits[i].v, want.v) << "stored " << stored << " ray " << i;
      }
    }
    EXPECT_GT(hit * 4, int(tiles.size())) << "the tiles should hit the slivers";
  }
  stored_normals_ = -1;
  const bool mt = GetParam().intersector == Intersector::mt;
  const BvhAccelerator long_ones(slivers, config(), options()),
      even(test::sphere(1.0f, 60, 80), config(), options());
  EXPECT_FALSE(long_ones.triangles().stores_normals());
  EXPECT_EQ(even.triangles().stores_normals(), mt && GetParam().isa != Isa::scalar);
  // the budget holds for the float kernels of the SIMD ISAs (8 or 16 lanes; double kernels have half)
  if (GetParam().isa != Isa::scalar && triangle_kernels(GetParam().isa, GetParam().intersector).width >= 8) {
    EXPECT_LE(double(long_ones.bytes()), kBvhBytesPerTriangle * double(slivers.size()));
    EXPECT_LE(double(even.bytes()), kBvhBytesPerTriangle * double(60 * 80 * 2));
  }
  if (mt) {  // the slivers would pass the budget with their normals
    stored_normals_ = 1;
    const BvhAccelerator stored(slivers, config(), options());
    EXPECT_GT(double(stored.bytes()), kBvhBytesPerTriangle * double(slivers.size()));
  }
}

// The default: stored `mt` normals unless the tree and its rows would pass the budget with them or
// the mesh is large; never for the other intersectors; the option overrides for `mt` only.
TEST(BvhNormals, StoredForMtOnSmallMeshesWithinTheBudget) {
  // 10,000 triangles and 40,000 bytes of nodes leave 600,000 bytes: 11,536 slots of 52 bytes (a
  // multiple of 16, one block of slack included), so 11,520 slots in use fit and 11,521 do not
  const std::size_t n = 10000, tree = 40000;
  ASSERT_EQ(TriangleSoA::kSlotBytes + TriangleSoA::kNormalBytes, 52u);
  EXPECT_EQ(bvh_normals(Intersector::mt, -1, tree, n, n), Normals::stored);
  EXPECT_EQ(bvh_normals(Intersector::mt, -1, tree, 11520, n), Normals::stored);
  EXPECT_EQ(bvh_normals(Intersector::mt, -1, tree, 11521, n), Normals::formed);
  EXPECT_EQ(bvh_normals(Intersector::mt, 1, tree, 2 * n, n), Normals::stored);
  EXPECT_EQ(bvh_normals(Intersector::mt, 0, tree, n, n), Normals::formed);
  EXPECT_EQ(bvh_normals(Intersector::mt, -1, 0, kFormedNormalsFrom - 1, kFormedNormalsFrom - 1),
            Normals::stored);
  EXPECT_EQ(bvh_normals(Intersector::mt, -1, 0, kFormedNormalsFrom, kFormedNormalsFrom), Normals::formed);
  for (const Intersector other :
       {Intersector::paper, Intersector::mt64, Intersector::watertight, Intersector::watertight64})
    for (const int option : {-1, 0, 1}) EXPECT_EQ(bvh_normals(other, option, tree, n, n), Normals::formed);
}

// The traversals' three leaf calls — through the kernel table, the float kernel called directly
// and its closest-hit kernel inlined (AVX2 and AVX-512) — all equal brute force, with tmin < 0,
// = 0 and > 0 (the direct `mt` calls pick the kernel's tmin = 0 form themselves), and on the
// hard-case families (edges, vertices, grazing and parallel rays, tiny and far triangles). With the `mt`
// intersector on AVX2 and AVX-512 the closest-hit traversals are three different functions, on the
// scalar ISA the same (table) one; on AVX2 the any-hit traversal's leaves are called directly too
// (with the ray's lanes formed once per ray), with and without a filter; on AVX-512 they are under
// every setting (one any-hit function). With `watertight` on AVX2 and AVX-512 both traversals call
// the kernel directly, the ray's shear formed once per ray. Inlining is closest-hit only.
TEST_P(BvhTraversal, EveryLeafCallMatchesBruteForce) {
  std::vector<Ray> rays = test::random_rays(1500, 1.5f, 21);
  for (std::size_t i = 0; i < rays.size(); ++i)
    rays[i].tmin = i % 3 == 0 ? 0.0f : (i % 3 == 1 ? 0.05f : -0.2f);
  // the hard cases where the leaf calls differ (the others' are all the table's; `paper` misses the
  // tiny families by contract)
  const Intersector in = GetParam().intersector;
  const std::vector<HardCaseFamily> hard = in == Intersector::mt || in == Intersector::watertight
                                               ? hard_case_families(31, 1)
                                               : std::vector<HardCaseFamily>{};
  for (const LeafCall call : {LeafCall::table, LeafCall::direct, LeafCall::inlined}) {
    leaf_call_ = int(call);
    expect_same(test::random_soup(2500, 0.1f, 22), rays);
    expect_same(test::sphere(1.0f, 30, 40), rays);
    for (const HardCaseFamily& f : hard) {
      if (f.degenerate) continue;  // never hit: expect_same wants a scene that tests something
      SCOPED_TRACE(f.name);
      expect_same(f.mesh, f.rays);
    }
  }
  BvhOptions table, direct, inlined;
  table.width = direct.width = inlined.width = GetParam().width;
  table.leaf_call = int(LeafCall::table);
  direct.leaf_call = int(LeafCall::direct);
  inlined.leaf_call = int(LeafCall::inlined);
  const TriangleMesh one = test::random_soup(10, 0.1f, 23);
  const BvhAccelerator a(one, config(), table), b(one, config(), direct), c(one, config(), inlined);
  const bool simd = GetParam().isa != Isa::scalar;
  const bool mt = simd && in == Intersector::mt, watertight = simd && in == Intersector::watertight;
  if (mt || watertight) {
    EXPECT_NE(a.traversal().closest, b.traversal().closest);
  } else {
    EXPECT_EQ(a.traversal().closest, b.traversal().closest);  // no direct form: both the table call
  }
  if (mt || watertight) {
    EXPECT_NE(b.traversal().closest, c.traversal().closest);
  } else {
    EXPECT_EQ(b.traversal().closest, c.traversal().closest);  // no inlined form: the table's
  }
  if ((mt && GetParam().isa == Isa::avx2) || watertight) {
    EXPECT_NE(a.traversal().occluded, b.traversal().occluded);
  } else {
    EXPECT_EQ(a.traversal().occluded, b.traversal().occluded);
  }
  EXPECT_EQ(b.traversal().occluded, c.traversal().occluded);  // inlining is closest-hit only
  EXPECT_EQ(a.traversal().leaf_call, LeafCall::table);
  EXPECT_EQ(b.traversal().leaf_call, mt || watertight ? LeafCall::direct : LeafCall::table);
  EXPECT_EQ(c.traversal().leaf_call, mt || watertight ? LeafCall::inlined : LeafCall::table);
}

TEST(BvhTraversalRule, MtAndWatertightLeavesCalledDirectlyOnAvx2AndAvx512InlinedOnLargeTrees) {
  const std::size_t small = kWideNodeTriangles - 1, large = kWideNodeTriangles;
  for (const Isa isa : {Isa::avx512, Isa::avx2}) {
    for (const Intersector direct : {Intersector::mt, Intersector::watertight}) {
      EXPECT_EQ(default_leaf_call(isa, direct, small), LeafCall::direct);
      EXPECT_EQ(default_leaf_call(isa, direct, large), LeafCall::inlined);
    }
    for (const Intersector other : {Intersector::paper, Intersector::mt64, Intersector::watertight64})
      EXPECT_EQ(default_leaf_call(isa, other, large), LeafCall::table);
  }
  for (const Intersector any : {Intersector::mt, Intersector::watertight, Intersector::paper})
    EXPECT_EQ(default_leaf_call(Isa::scalar, any, large), LeafCall::table);
}

TEST_P(BvhTraversal, MatchesBruteForceWithLargeLeavesAndFewBins) {
  SahConfig sah;
  sah.max_leaf = 32;
  sah.leaf_block = 16;
  sah.bins = 4;
  expect_same(test::random_soup(1500, 0.2f, 5), test::random_rays(1000, 1.5f, 6), sah);
}

TEST_P(BvhTraversal, MatchesBruteForceOnClosedSphereFromInsideAndOutside) {
  const TriangleMesh s = test::sphere(1.0f, 30, 40);
  expect_same(s, test::random_rays(1000, 0.9f, 7));  // inside: every ray hits
  expect_same(s, test::random_rays(1000, 2.0f, 8));
}

TEST_P(BvhTraversal, MatchesBruteForceOnCoplanarTrianglesAndAxisParallelRays) {
  const TriangleMesh g = test::flat_grid(20);
  std::vector<Ray> rays = test::random_rays(1000, 10.0f, 9);
  for (int i = 0; i <= 40; ++i) {
    const float x = float(i) * 0.5f;  // through vertices and along edges
    rays.push_back(Ray{{x, x * 0.5f, 5.0f}, {0.0f, 0.0f, -1.0f}});
    rays.push_back(Ray{{x, 3.0f, -5.0f}, {-0.0f, 0.0f, 2.0f}});
    rays.push_back(Ray{{-1.0f, x, 0.0f}, {1.0f, 0.0f, 0.0f}});     // in the plane
    rays.push_back(Ray{{x, -1.0f, 1e-30f}, {0.0f, 1.0f, -0.0f}});  // parallel, just above
  }
  expect_same(g, rays);
}

// tmin < 0 takes the box test with per-node widening, tmin >= 0 (also -0) the forward one whose
// widening is folded into scaled reciprocals (single_ray_traversal.inl): both must equal brute force.
TEST_P(BvhTraversal, MatchesBruteForceWithNegativeAndZeroTmin) {
  std::vector<Ray> rays = test::random_rays(1200, 1.5f, 15);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (i % 3 == 0) rays[i].tmin = -(0.05f + 0.4f * float(i % 9));
    if (i % 3 == 1) rays[i].tmin = -0.0f;
  }
  expect_same(test::random_soup(1500, 0.1f, 16), rays);
  expect_same(test::sphere(1.0f, 30, 40), rays);
  // a flat grid (zero-thickness boxes) behind origins pointing away from it: only a negative tmin
  // reaches it, where scaled reciprocals would make entry > exit and miss (the `paper` kernel
  // accepts t > 1e-6 only, so every fourth ray points at the grid)
  std::vector<Ray> away;
  for (int i = 0; i < 200; ++i) {
    const float x = 0.37f + 0.093f * float(i), y = 0.21f + 0.071f * float(i % 50);
    const float dz = i % 4 == 0 ? -1.0f : 1.0f;
    away.push_back(Ray{{x, y, 1.0f + 0.01f * float(i % 7)}, {0.01f * float(i % 5), 0.0f, dz}, -3.0f});
  }
  expect_same(test::flat_grid(20), away);
}

TEST_P(BvhTraversal, MatchesBruteForceOnTinyAndEmptyMeshes) {
  const std::vector<Ray> rays = test::random_rays(500, 1.5f, 10);
  TriangleMesh one;
  one.add_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  expect_same(one, rays);
  expect_same(TriangleMesh{}, rays);
  TriangleMesh same;  // many copies of one triangle: every tie goes to id 0
  for (int i = 0; i < 100; ++i) same.add_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  expect_same(same, rays);
}

// Triangles at exponentially growing distances make the SAH peel off a few triangles per level: a
// deep, unbalanced tree (its stack bound is depth · (width − 1) + 1, computed at build time).
TEST_P(BvhTraversal, DeepTreesMatchBruteForce) {
  TriangleMesh chain;
  float x = 1.0f;
  for (int i = 0; i < 150; ++i, x *= 1.4f) chain.add_triangle({x, -1, -1}, {x, 1, -1}, {x * 1.01f, 0, 1});
  SahConfig sah;
  sah.max_leaf = 1;
  sah.leaf_block = 1;
  merge_steps_ = 0;  // merging would fold the chain's bottom into a few leaves
  const BvhAccelerator bvh(chain, config(), options(sah));
  EXPECT_GE(bvh.tree().depth(), 8u) << "the chain should make a deep tree";
  std::vector<Ray> rays;
  for (int i = 0; i < 200; ++i) {
    rays.push_back(Ray{{0.5f, 0.01f * float(i % 7), 0.0f}, {1.0f, 0.0f, 0.001f * float(i % 5)}});
    rays.push_back(Ray{{1e20f, 0.0f, 0.0f}, {-1.0f, 0.001f * float(i % 3), 0.0f}});
  }
  expect_same(chain, rays, sah);
}

// Packets (closest_stream) give every ray exactly its single-ray answer: coherent camera tiles,
// incoherent random rays (the packet diverges at once), partial packets and untraceable lanes.
// Merged leaves (BvhOptions::merge_steps) cover the padding slots between the leaves they join:
// zero-area triangles at the origin with id −1. Rays through the origin (the shared vertex of a fan
// of triangles), along the fan's plane and across it never report one, and ties inside a merged
// leaf (the fan twice, the copy with higher ids) still go to the lowest id, as in brute force.
TEST_P(BvhTraversal, MergedLeavesWithPaddingMatchBruteForceThroughTheOrigin) {
  TriangleMesh mesh = test::random_soup(1500, 0.1f, 21);
  for (int copy = 0; copy < 2; ++copy)
    for (int k = 0; k < 8; ++k) {
      const float a = 0.785398f * float(k), b = 0.785398f * float(k + 1);
      mesh.add_triangle(Vec3f{0, 0, 0}, Vec3f{0.3f * std::cos(a), 0.3f * std::sin(a), 0},
                        Vec3f{0.3f * std::cos(b), 0.3f * std::sin(b), 0});
    }
  SahConfig sah;  // leaves of 1–3 triangles: many need padding to keep to their kernel steps
  sah.max_leaf = 3;
  sah.leaf_block = 3;
  const BvhAccelerator bvh(mesh, config(), options(sah));
  bool padding_in_a_leaf = false;
  test::for_each_leaf(bvh.tree(), [&](uint32_t begin, uint32_t count) {
    for (uint32_t s = begin; s < begin + count; ++s)
      padding_in_a_leaf = padding_in_a_leaf || bvh.triangles().id(s) < 0;
  });
  if (triangle_kernels(config().isa, config().intersector).width > 1) {  // scalar kernels need no padding
    EXPECT_TRUE(padding_in_a_leaf) << "no merged leaf covers padding: the case is not tested";
  }
  std::vector<Ray> rays;
  for (int i = 0; i < 300; ++i) {
    const float a = 0.021f * float(i), h = 0.05f + 0.01f * float(i % 11);
    const Vec3f from{std::cos(a) * 0.2f, std::sin(a) * 0.2f, (i % 2 ? h : -h)};
    rays.push_back(Ray{from, Vec3f{0, 0, 0} - from});                           // through the origin
    rays.push_back(Ray{Vec3f{from.x, from.y, 0}, Vec3f{-from.x, -from.y, 0}});  // in the plane
    rays.push_back(Ray{from, Vec3f{0.01f * float(i % 7), 0.013f * float(i % 5), -from.z}});
  }
  expect_same(mesh, rays, sah);
}

TEST_P(BvhTraversal, PacketsMatchSingleRays) {
  const TriangleMesh s = test::sphere(1.0f, 30, 40);
  BvhOptions options;
  options.width = GetParam().width;
  const BvhAccelerator bvh(s, config(), options);
  std::vector<Ray> rays;
  for (int y = 0; y < 32; ++y)  // 4x4 tiles of a camera at z = 3 looking at the sphere
    for (int x = 0; x < 32; ++x) {
      const int px = (y / 4 % 8) * 4 + x % 4, py = (x / 4) * 4 + y % 4;
      rays.push_back(Ray{{0, 0, 3}, {(px - 16) / 20.0f, (py - 16) / 20.0f, -1.0f}});
    }
  for (const Ray& r : test::random_rays(600, 1.5f, 13)) rays.push_back(r);
  rays[5].org.x = std::nanf("");  // an untraceable lane inside a packet
  rays[40].tmax = 2.5f;
  const std::size_t n = rays.size() - 3;  // a partial packet at the end
  std::vector<Hit> stream(n);
  bvh.closest_stream(rays.data(), stream.data(), n);
  int hits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Hit single = bvh.closest(rays[i]);
    ASSERT_EQ(single.tri, stream[i].tri) << "ray " << i;
    ASSERT_EQ(single.t, stream[i].t) << "ray " << i;
    ASSERT_EQ(single.u, stream[i].u) << "ray " << i;
    hits += single.hit();
  }
  EXPECT_GT(hits, 200);
}

// The BVH's contract: a NaN or infinite origin or direction, or a NaN tmin/tmax, never hits.
TEST_P(BvhTraversal, NonFiniteRaysMiss) {
  const TriangleMesh s = test::sphere(1.0f, 10, 10);
  const float nan = std::nanf(""), inf = kInf;
  const BvhAccelerator bvh(s, config());
  for (const Ray& r :
       {Ray{{nan, 0, 0}, {1, 0, 0}}, Ray{{0, 0, 0}, {nan, 1, 0}}, Ray{{inf, 0, 0}, {-1, 0, 0}},
        Ray{{0, 0, 0}, {inf, 0, 0}}, Ray{{0, 0, 0}, {1, 0, 0}, nan, 5}, Ray{{0, 0, 0}, {1, 0, 0}, 0, nan}}) {
    EXPECT_EQ(bvh.closest(r).tri, -1);
    EXPECT_FALSE(bvh.occluded(r));
  }
  // a zero direction and an infinite interval are legal
  expect_same(s, {Ray{{0, 0, 0}, {0, 0, 0}}, Ray{{0, 0, 0}, {1, 0, 0}, -inf, inf}});
}

INSTANTIATE_TEST_SUITE_P(AllIsasIntersectorsWidths, BvhTraversal,
                         ::testing::ValuesIn(test::bvh_cases({std::begin(kAllIntersectors),
                                                              std::end(kAllIntersectors)})),
                         test::bvh_case_name);

}  // namespace
}  // namespace rayvec
