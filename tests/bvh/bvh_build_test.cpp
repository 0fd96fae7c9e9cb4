// Structure of the built trees: with object splits only, every triangle in exactly one leaf (with
// spatial splits, in one or more: spatial_split_test.cpp), ids increasing inside a leaf (merged
// leaves included), child boxes inside their parents' slots, the stack bound, and determinism
// across thread counts (spatial splits included); the TriangleSoA the leaves index, filled in
// parallel.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "bvh/binary_bvh.h"
#include "bvh/leaf_alignment.h"
#include "bvh/wide_bvh.h"
#include "kernels/triangle_soa.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

// The builder's configuration without spatial splits: each triangle in exactly one leaf.
SahConfig object_splits(SahConfig sah = {}) {
  sah.split_budget = 0.0f;
  return sah;
}

// `order`: the slots' triangles (bin.order, after sort_leaf_slots when leaves were merged).
template <int N>
void check_wide(const WideBvh& bvh, const TriangleMesh& mesh, const BinaryBvh& bin,
                const std::vector<uint32_t>* sorted = nullptr) {
  const std::vector<uint32_t>& order = sorted ? *sorted : bin.order;
  const auto* nodes = static_cast<const WideNode<N>*>(bvh.arrays().nodes);
  std::vector<int> seen(mesh.size(), 0);
  uint32_t leaves = 0;
  for (uint32_t n = 0; n < bvh.node_count(); ++n)
    for (int k = 0; k < N; ++k) {
      const uint32_t ref = nodes[n].ref[k];
      if (ref == kEmptyRef || !(ref & kLeafFlag)) continue;
      ++leaves;
      const uint32_t begin = (ref >> 5) & (kMaxLeafBegin - 1), end = begin + (ref & 31) + 1;
      for (uint32_t s = begin; s < end; ++s) {
        const uint32_t tri = order[s];
        if (s > begin && tri != TriangleSoA::kPaddingSlot) {
          EXPECT_LT(order[s - 1], tri) << "ids must increase inside a leaf, padding last";
        }
        if (tri == TriangleSoA::kPaddingSlot) continue;  // only merged leaves cover padding
        ++seen[tri];
        for (int c = 0; c < 3; ++c) {  // the child box holds the triangle
          const Vec3f p = mesh.vertex(tri, c);
          for (int a = 0; a < 3; ++a) {
            EXPECT_LE(nodes[n].bounds[a][k], p[a]);
            EXPECT_GE(nodes[n].bounds[a + 3][k], p[a]);
          }
        }
      }
    }
  EXPECT_EQ(leaves, bvh.leaf_count());
  for (std::size_t t = 0; t < mesh.size(); ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t;
  EXPECT_EQ(bvh.arrays().stack_size, bvh.depth() * uint32_t(N - 1) + 1);
}

TEST(BinnedSahBuilder, EveryTriangleInExactlyOneSortedLeafForEveryWidth) {
  const TriangleMesh mesh = test::random_soup(5000, 0.05f, 11);
  const BinaryBvh bin = build_binned_sah(mesh, object_splits());
  check_wide<4>(WideBvh(bin, 4), mesh, bin);
  check_wide<8>(WideBvh(bin, 8), mesh, bin);
  check_wide<16>(WideBvh(bin, 16), mesh, bin);
}

// Merging (WideBvh's merge_slots): subtrees whose leaves lie within merge_slots slots become one
// leaf, padding between them included; sort_leaf_slots sorts each such range, padding last. Fewer
// nodes, the same triangles, every leaf range within the limit.
// Returns whether a merged leaf covers padding.
template <int N>
bool check_merged(const TriangleMesh& mesh, uint32_t step, uint32_t merge_slots) {
  SahConfig sah;
  sah.leaf_block = step;
  sah.max_leaf = 2 * step;
  BinaryBvh bin = build_binned_sah(mesh, object_splits(sah));
  align_leaves(bin, step);
  const WideBvh plain(bin, N);
  const WideBvh merged(bin, N, CollapseRule::lower_sah_cost, merge_slots);
  std::vector<uint32_t> order = bin.order, one_thread = bin.order;  // leaves sort in parallel
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  sort_leaf_slots(merged, one_thread);
  omp_set_num_threads(2);
  sort_leaf_slots(merged, order);
  omp_set_num_threads(threads);
  EXPECT_EQ(order, one_thread) << N << "-wide";
  check_wide<N>(merged, mesh, bin, &order);
  EXPECT_LT(merged.node_count(), plain.node_count()) << N << "-wide";
  EXPECT_LT(merged.leaf_count(), plain.leaf_count()) << N << "-wide";
  const auto* nodes = static_cast<const WideNode<N>*>(merged.arrays().nodes);
  bool padding_covered = false;
  for (uint32_t n = 0; n < merged.node_count(); ++n)
    for (const uint32_t ref : nodes[n].ref) {
      if (ref == kEmptyRef || !(ref & kLeafFlag)) continue;
      const uint32_t begin = (ref >> 5) & (kMaxLeafBegin - 1), count = (ref & 31) + 1;
      EXPECT_LE(count, std::max(merge_slots, sah.max_leaf));
      for (uint32_t s = begin; s < begin + count; ++s)
        padding_covered = padding_covered || order[s] == TriangleSoA::kPaddingSlot;
    }
  return padding_covered;
}

TEST(WideBvhMerge, SubtreesOfFewSlotsBecomeOneSortedLeaf) {
  const TriangleMesh mesh = test::random_soup(20000, 0.02f, 17);
  const bool padding = check_merged<8>(mesh, 8, 24) | check_merged<16>(mesh, 8, 32) |
                       check_merged<16>(mesh, 4, 24) | check_merged<4>(mesh, 4, 12);
  EXPECT_TRUE(padding) << "no merged leaf joins leaves across padding: that case is not checked";
  EXPECT_THROW(WideBvh(build_binned_sah(mesh), 8, CollapseRule::lower_sah_cost, 33), std::invalid_argument);
}

TEST(BinnedSahBuilder, CoincidentTrianglesSplitByMedianWithLogDepth) {
  TriangleMesh mesh;  // SAH cannot separate them; the object-median fallback must
  for (int i = 0; i < 4096; ++i) mesh.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const BinaryBvh bin = build_binned_sah(mesh, object_splits());
  const WideBvh wide(bin, 8);
  check_wide<8>(wide, mesh, bin);
  EXPECT_LE(wide.depth(), 8u);  // 4096 / 8 per leaf = 512 leaves: log8(512) = 3 levels, some slack
}

TEST(BinnedSahBuilder, SameTreeForOneAndTwoThreads) {
  const TriangleMesh mesh = test::random_soup(20000, 0.02f, 12);
  SahConfig config;
  config.task_threshold = 256;  // make sure tasks run
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const BinaryBvh one = build_binned_sah(mesh, config);
  omp_set_num_threads(2);
  const BinaryBvh two = build_binned_sah(mesh, config);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.order, two.order);
  const WideBvh a(one, 8), b(two, 8);
  ASSERT_EQ(a.node_count(), b.node_count());
  EXPECT_EQ(0, std::memcmp(a.arrays().nodes, b.arrays().nodes, a.bytes()));
}

TEST(BinnedSahBuilder, SameTreeWhenTheTopLevelsPartitionInParallel) {
  // 70,000 triangles: ranges of 2^16 or more are partitioned by chunked tasks (two threads) or in
  // place (one thread); the tree must not depend on which
  const TriangleMesh mesh = test::random_soup(70000, 0.01f, 13);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const BinaryBvh one = build_binned_sah(mesh, object_splits());
  omp_set_num_threads(2);
  const BinaryBvh two = build_binned_sah(mesh, object_splits());
  omp_set_num_threads(threads);
  EXPECT_EQ(one.order, two.order);
  const WideBvh a(one, 8), b(two, 8);
  check_wide<8>(b, mesh, two);
  ASSERT_EQ(a.node_count(), b.node_count());
  EXPECT_EQ(0, std::memcmp(a.arrays().nodes, b.arrays().nodes, a.bytes()));
}

TEST(TriangleSoA, ParallelFillWritesEverySlotInOrder) {
  // above the parallel threshold, and large enough that the fill fetches the mesh ahead
  const TriangleMesh mesh = test::random_soup(40000, 0.05f, 14);
  std::vector<uint32_t> order(mesh.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = uint32_t(order.size()) - 1 - i;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  const TriangleSoA soa(mesh, order);
  omp_set_num_threads(threads);
  ASSERT_EQ(soa.size(), mesh.size());
  for (uint32_t s = 0; s < soa.size(); ++s) {
    ASSERT_EQ(soa.id(s), int32_t(order[s]));
    for (int c = 0; c < 3; ++c) {
      const Vec3f p = c == 0 ? soa.v0(s) : (c == 1 ? soa.v1(s) : soa.v2(s)), q = mesh.vertex(order[s], c);
      ASSERT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z) << "slot " << s;
    }
  }
  for (uint32_t s = soa.size(); s < soa.padded_size(); ++s) {  // padding: id -1, zero area
    ASSERT_EQ(soa.id(s), -1);
    const Vec3f p = soa.v0(s), q = soa.v1(s), r = soa.v2(s);
    ASSERT_TRUE(p.x == 0 && q.y == 0 && r.z == 0 && soa.arrays().v1x[slot_offset(s)] == 0 &&
                soa.arrays().ng[normal_offset(s) + 2 * kSlotBlock] == 0);
  }
}

TEST(BinnedSahBuilder, EmptyAndSingleTriangleMeshes) {
  const BinaryBvh empty = build_binned_sah(TriangleMesh{});
  EXPECT_TRUE(empty.nodes.empty());
  const WideBvh wide_empty(empty, 8);
  EXPECT_EQ(wide_empty.node_count(), 1u);
  EXPECT_EQ(wide_empty.leaf_count(), 0u);
  TriangleMesh one;
  one.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const BinaryBvh bin = build_binned_sah(one, object_splits());
  check_wide<8>(WideBvh(bin, 8), one, bin);
}

}  // namespace
}  // namespace rayvec
