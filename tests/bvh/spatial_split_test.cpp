// Spatial splits: a clipped reference bounds every point of its triangle on its side of the plane
// (computed in double, so float rounding cannot hide a miss); the builder references long
// triangles in several leaves within its budget, and every point of every triangle lies in the box
// of a leaf that holds it. The traversal tests (bvh_traversal_test.cpp, bvh_packet_test.cpp) check
// that a BVH over such a tree returns brute force's hits.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "bvh/binary_bvh.h"
#include "bvh/spatial_split.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

struct Point {
  double p[3];
};

// Points of triangle `tri` in double: its corners, edge points and interior samples.
std::vector<Point> samples(const TriangleMesh& mesh, uint32_t tri, std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> w(0.0, 1.0);
  std::vector<Point> out;
  const Vec3f v[3] = {mesh.vertex(tri, 0), mesh.vertex(tri, 1), mesh.vertex(tri, 2)};
  for (int i = 0; i < n; ++i) {
    double a = w(rng), b = w(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    if (i < 3) a = i == 1, b = i == 2;         // the corners
    if (i >= 3 && i < 9) (i % 2 ? a : b) = 0;  // on edges
    Point q;
    for (int c = 0; c < 3; ++c)
      q.p[c] = (1 - a - b) * double(v[0][c]) + a * double(v[1][c]) + b * double(v[2][c]);
    out.push_back(q);
  }
  return out;
}

// Whether q lies in the box, up to the double rounding of q itself (a few ulps of a double, far
// below a float's: a box that misses a point by float rounding still fails).
bool inside(const Point& q, const float* lo, const float* hi) {
  for (int c = 0; c < 3; ++c) {
    const double tol = 1e-12 * std::max(1.0, std::fabs(q.p[c]));
    if (!(double(lo[c]) - tol <= q.p[c] && q.p[c] <= double(hi[c]) + tol)) return false;
  }
  return true;
}

BuildPrim whole(const TriangleMesh& mesh, uint32_t tri) {
  BuildPrim r{{INFINITY, INFINITY, INFINITY}, tri, {-INFINITY, -INFINITY, -INFINITY}, 0.0f};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) {
      r.lo[c] = std::min(r.lo[c], mesh.vertex(tri, k)[c]);
      r.hi[c] = std::max(r.hi[c], mesh.vertex(tri, k)[c]);
    }
  return r;
}

// Triangles at scales 1e-3 to 1e4 and offsets up to 1e4, some with a corner on the plane.
TEST(SpatialSplitter, ClippedPartsHoldEveryPointOnTheirSide) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), f(0.0f, 1.0f);
  TriangleMesh mesh;
  for (int i = 0; i < 300; ++i) {
    const float scale = std::pow(10.0f, float(i % 8) - 3.0f), offset = i % 3 == 0 ? 1e4f * u(rng) : 0.0f;
    const Vec3f o{offset, offset * 0.5f, -offset};
    auto corner = [&] { return o + Vec3f{u(rng), u(rng), u(rng)} * scale; };
    mesh.add_triangle(corner(), corner(), corner());
  }
  const SpatialSplitter splitter(mesh, 16, 16);
  int both = 0;
  for (uint32_t t = 0; t < mesh.size(); ++t) {
    const BuildPrim r = whole(mesh, t);
    const int axis = int(t % 3);
    const float at = t % 5 == 0 ? mesh.vertex(t, 1)[axis] : r.lo[axis] + (r.hi[axis] - r.lo[axis]) * f(rng);
    BuildPrim left, right;
    bool has_left, has_right;
    splitter.clip(r, axis, at, left, right, has_left, has_right);
    both += has_left && has_right;
    EXPECT_TRUE(has_left || has_right);
    if (has_left) {
      EXPECT_LE(left.hi[axis], at);
      EXPECT_EQ(left.id, t);
    }
    if (has_right) {
      EXPECT_GE(right.lo[axis], at);
    }
    for (const BuildPrim* side : {&left, &right})
      for (int c = 0; c < 3; ++c) {  // inside the clipped reference
        if (!(side == &left ? has_left : has_right)) continue;
        EXPECT_GE(side->lo[c], r.lo[c]);
        EXPECT_LE(side->hi[c], r.hi[c]);
      }
    for (const Point& q : samples(mesh, t, rng, 200)) {
      if (q.p[axis] <= double(at)) {
        ASSERT_TRUE(has_left && inside(q, left.lo, left.hi)) << "triangle " << t << " left of " << at;
      }
      if (q.p[axis] >= double(at)) {
        ASSERT_TRUE(has_right && inside(q, right.lo, right.hi)) << "triangle " << t << " right of " << at;
      }
    }
    // a second cut of the left part, on another axis, still holds the points in both half-spaces
    if (!has_left) continue;
    const int b = (axis + 1) % 3;
    const float at2 = left.lo[b] + (left.hi[b] - left.lo[b]) * 0.5f;
    BuildPrim ll, lr;
    bool has_ll, has_lr;
    splitter.clip(left, b, at2, ll, lr, has_ll, has_lr);
    for (const Point& q : samples(mesh, t, rng, 200)) {
      if (q.p[axis] > double(at)) continue;
      if (q.p[b] <= double(at2)) {
        ASSERT_TRUE(has_ll && inside(q, ll.lo, ll.hi)) << "triangle " << t;
      }
      if (q.p[b] >= double(at2)) {
        ASSERT_TRUE(has_lr && inside(q, lr.lo, lr.hi)) << "triangle " << t;
      }
    }
  }
  EXPECT_GT(both, 200) << "the planes should cut most triangles";
}

TEST(SpatialSplitter, ASideWithoutAPartIsEmpty) {
  TriangleMesh mesh;
  mesh.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const SpatialSplitter splitter(mesh, 16, 16);
  BuildPrim left, right;
  bool has_left, has_right;
  splitter.clip(whole(mesh, 0), 0, 2.0f, left, right, has_left, has_right);
  EXPECT_TRUE(has_left);
  EXPECT_FALSE(has_right);
  // the reference's box already excludes the triangle's part beyond x = 0.5
  BuildPrim part = whole(mesh, 0);
  part.hi[0] = 0.5f;
  splitter.clip(part, 0, 0.75f, left, right, has_left, has_right);
  EXPECT_TRUE(has_left);
  EXPECT_FALSE(has_right);
}

// Leaves of the binary tree as (box, ids).
void expect_covered(const TriangleMesh& mesh, const BinaryBvh& tree) {
  std::vector<std::vector<uint32_t>> leaves_of(mesh.size());
  for (uint32_t k = 0; k < tree.nodes.size(); ++k) {
    const BinaryNode& n = tree.nodes[k];
    if (!n.leaf()) continue;
    for (uint32_t s = n.first; s < n.first + n.count; ++s) {
      if (s > n.first) {
        EXPECT_LT(tree.order[s - 1], tree.order[s]) << "ids increase inside a leaf";
      }
      leaves_of[tree.order[s]].push_back(k);
    }
  }
  std::mt19937 rng(9);
  for (uint32_t t = 0; t < mesh.size(); ++t) {
    ASSERT_FALSE(leaves_of[t].empty()) << "triangle " << t << " in no leaf";
    for (const Point& q : samples(mesh, t, rng, 60)) {
      bool found = false;
      for (const uint32_t k : leaves_of[t]) {
        const BBox& b = tree.nodes[k].box;
        const float lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
        found = found || inside(q, lo, hi);
      }
      ASSERT_TRUE(found) << "a point of triangle " << t << " is in none of its leaves' boxes";
    }
  }
}

TEST(BinnedSahBuilder, SpatialSplitsReferenceLongTrianglesInSeveralLeavesWithinTheBudget) {
  const TriangleMesh mesh = test::long_slivers(3000, 3);
  SahConfig sah;
  sah.max_leaf = 16;
  sah.leaf_block = 8;
  sah.split_budget = 0.0f;
  const BinaryBvh plain = build_binned_sah(mesh, sah);
  EXPECT_EQ(plain.order.size(), mesh.size());
  sah.split_budget = 0.3f;
  const BinaryBvh split = build_binned_sah(mesh, sah);
  EXPECT_GT(split.order.size(), mesh.size() + mesh.size() / 10) << "few duplicates: splits not tried?";
  EXPECT_LE(split.order.size(), mesh.size() + std::size_t(0.3 * double(mesh.size())));
  expect_covered(mesh, split);
  // deterministic for any number of threads
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const BinaryBvh again = build_binned_sah(mesh, sah);
    EXPECT_EQ(again.order, split.order);
  }
}

// A mesh of small, even triangles (the bumpy spheres of the benchmarks): object splits are nearly
// disjoint, so no spatial split is tried and the tree is the one without the budget.
TEST(BinnedSahBuilder, NoSpatialSplitsOnAMeshOfSmallEvenTriangles) {
  const TriangleMesh mesh = test::sphere(1.0f, 40, 80);
  SahConfig sah;
  sah.split_budget = 0.0f;
  const BinaryBvh plain = build_binned_sah(mesh, sah);
  sah.split_budget = 0.3f;
  const BinaryBvh split = build_binned_sah(mesh, sah);
  EXPECT_EQ(split.order, plain.order);
}

}  // namespace
}  // namespace rayvec
