// align_leaves: every leaf takes as few kernel steps as its size needs (padding only where it would
// otherwise straddle one more step, so small leaves share steps; siblings trade places where that
// saves padding, to the least any order of siblings gives), keeps its triangles in their
// order, and only padding slots fill the gaps; the wide BVH built from the aligned tree still holds
// every triangle exactly once, and the TriangleSoA turns padding entries into id −1 slots.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "accel/bvh_accelerator.h"
#include "bvh/binary_bvh.h"
#include "bvh/bvh_traversal.h"
#include "bvh/leaf_alignment.h"
#include "bvh/wide_bvh.h"
#include "platform/isa.h"
#include "kernels/triangle_soa.h"
#include "bvh_scenes.h"
#include "wide_leaves.h"

namespace rayvec {
namespace {

std::vector<std::vector<uint32_t>> leaf_contents(const BinaryBvh& tree) {
  std::vector<std::vector<uint32_t>> out;
  for (const BinaryNode& n : tree.nodes)
    if (n.leaf()) out.emplace_back(tree.order.begin() + n.first, tree.order.begin() + n.first + n.count);
  return out;
}

uint32_t steps(uint32_t first, uint32_t count, uint32_t step) {
  return (first % step + count + step - 1) / step;
}

TEST(LeafAlignment, LeavesTakeTheFewestStepsAndKeepTheirTriangles) {
  const TriangleMesh mesh = test::random_soup(3000, 0.05f, 5);
  for (uint32_t step : {1u, 8u, 16u}) {
    BinaryBvh tree = build_binned_sah(mesh);
    const auto before = leaf_contents(tree);
    const std::size_t slots_before = tree.order.size();
    align_leaves(tree, step);
    EXPECT_EQ(leaf_contents(tree), before) << "step " << step;
    std::vector<int> covered(tree.order.size(), 0);
    std::size_t extra_steps = 0, unaligned = 0, aligned_padding = 0, slots = 0;
    std::vector<std::pair<uint32_t, uint32_t>> leaves;  // (first, count) in slot order
    for (const BinaryNode& n : tree.nodes) {
      if (!n.leaf()) continue;
      leaves.emplace_back(n.first, n.count);
      extra_steps += steps(n.first, n.count, step) - steps(0, n.count, step);
      unaligned += n.first % step != 0;
      for (uint32_t s = n.first; s < n.first + n.count; ++s) ++covered[s];
    }
    std::sort(leaves.begin(), leaves.end());
    for (const auto& [first, count] : leaves) {  // the padding of every leaf aligned, for comparison
      aligned_padding += (step - slots % step) % step;
      slots += (step - slots % step) % step + count;
    }
    EXPECT_EQ(extra_steps, 0u) << "step " << step;
    std::size_t padding = 0;
    for (std::size_t s = 0; s < tree.order.size(); ++s) {
      const bool pad = tree.order[s] == TriangleSoA::kPaddingSlot;
      padding += pad;
      EXPECT_EQ(covered[s], pad ? 0 : 1) << "slot " << s;
    }
    EXPECT_EQ(tree.order.size() - padding, slots_before);
    if (step == 1) {
      EXPECT_EQ(padding, 0u);
    } else {
      EXPECT_GT(unaligned, 0u) << "step " << step << ": small leaves should share steps";
      EXPECT_LT(padding, aligned_padding) << "step " << step;
    }
    if (step == 16) {
      EXPECT_GT(padding, 0u);  // 3000 random triangles do not tile 16-slot steps
    }
  }
}

std::size_t padding_slots(const BinaryBvh& tree) {
  return std::size_t(std::count(tree.order.begin(), tree.order.end(), TriangleSoA::kPaddingSlot));
}

// Padding slots of the layout that puts the first child first at every inner node, except at the
// nodes whose bit is set in `swapped` (bit j: the j-th inner node in index order); the trailing
// gap after the last leaf is not counted (align_leaves leaves none).
std::size_t padding_with_swaps(const BinaryBvh& tree, uint32_t swapped, uint32_t step) {
  std::vector<uint32_t> inner_rank(tree.nodes.size(), 0);
  uint32_t rank = 0;
  for (uint32_t k = 0; k < tree.nodes.size(); ++k)
    if (!tree.nodes[k].leaf()) inner_rank[k] = rank++;
  std::size_t slots = 0, padding = 0;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const uint32_t k = stack.back();
    stack.pop_back();
    const BinaryNode& n = tree.nodes[k];
    if (n.leaf()) {
      if (steps(slots, n.count, step) > steps(0, n.count, step)) {
        padding += (step - slots % step) % step;
        slots += (step - slots % step) % step;
      }
      slots += n.count;
      continue;
    }
    const bool second_first = inner_rank[k] < 32 && ((swapped >> inner_rank[k]) & 1);
    stack.push_back(second_first ? n.first : n.first + 1);
    stack.push_back(second_first ? n.first + 1 : n.first);
  }
  return padding;
}

// A root over a leaf of 5 and a node over leaves of 5 and 3: in tree order the second 5 needs a
// new step (3 padding slots); with the node's children traded, 5 + 3 fill a step and none are needed.
TEST(LeafAlignment, SiblingsTradePlacesWhenThatSavesPadding) {
  BinaryBvh tree;
  tree.nodes.resize(5);
  tree.nodes[0] = BinaryNode{BBox{}, 1, 0};
  tree.nodes[1] = BinaryNode{BBox{}, 0, 5};
  tree.nodes[2] = BinaryNode{BBox{}, 3, 0};
  tree.nodes[3] = BinaryNode{BBox{}, 5, 5};
  tree.nodes[4] = BinaryNode{BBox{}, 10, 3};
  for (uint32_t id = 0; id < 13; ++id) tree.order.push_back(id);
  const auto before = leaf_contents(tree);
  ASSERT_EQ(padding_with_swaps(tree, 0, 8), 3u);
  align_leaves(tree, 8);
  EXPECT_EQ(leaf_contents(tree), before);
  EXPECT_EQ(padding_slots(tree), 0u);
  EXPECT_EQ(tree.order.size(), 13u);
  EXPECT_EQ(tree.nodes[1].first, 0u);
  EXPECT_EQ(tree.nodes[4].first, 5u);  // the leaf of 3 shares the first step
  EXPECT_EQ(tree.nodes[3].first, 8u);
}

// The padding align_leaves leaves is the least of every assignment of which child goes first, found
// by trying them all on small trees with leaves of every size.
TEST(LeafAlignment, PaddingIsTheLeastAnyOrderOfSiblingsGives) {
  SahConfig small_leaves;
  small_leaves.max_leaf = 12;
  small_leaves.leaf_block = 3;
  small_leaves.traversal_cost = 3;
  small_leaves.split_budget = 0;
  int improved = 0;  // cases where tree order is not the least: the test must be able to fail
  for (uint64_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const TriangleMesh mesh = test::random_soup(90, 0.2f, seed);
    const BinaryBvh built = build_binned_sah(mesh, small_leaves);
    uint32_t inner = 0;
    for (const BinaryNode& n : built.nodes) inner += n.leaf() ? 0 : 1;
    ASSERT_LE(inner, 16u) << "seed " << seed << ": too many orders to try";
    for (uint32_t step : {4u, 8u, 16u}) {
      const std::size_t in_tree_order = padding_with_swaps(built, 0, step);
      std::size_t least = in_tree_order;
      for (uint32_t swapped = 1; swapped < (1u << inner); ++swapped)
        least = std::min(least, padding_with_swaps(built, swapped, step));
      BinaryBvh tree = built;
      align_leaves(tree, step);
      EXPECT_EQ(padding_slots(tree), least) << "seed " << seed << ", step " << step;
      EXPECT_EQ(leaf_contents(tree), leaf_contents(built));
      // the chosen layout's padding is known before the copy: the order is allocated at its size
      EXPECT_EQ(tree.order.capacity(), tree.order.size());
      improved += least < in_tree_order;
    }
  }
  EXPECT_GT(improved, 6);
}

// `tree` under a new root whose first child is a leaf of `count` new triangles (ids after the
// tree's): a leaf just below the root, above the levels where the threads share the work out.
BinaryBvh with_leaf_beside(const BinaryBvh& tree, uint32_t count) {
  BinaryBvh out;
  const auto slots = uint32_t(tree.order.size());
  out.nodes.push_back(BinaryNode{BBox{}, 1, 0});
  out.nodes.push_back(BinaryNode{BBox{}, slots, count});
  for (BinaryNode n : tree.nodes) {  // every old node moves two places on
    if (!n.leaf()) n.first += 2;
    out.nodes.push_back(n);
  }
  out.order = tree.order;
  for (uint32_t i = 0; i < count; ++i) out.order.push_back(slots + i);
  return out;
}

// Large trees are aligned by several threads, each choosing and laying out its own subtrees: the
// slots and every leaf's place are those of one thread, at steps that reorder siblings and at one
// too large to (whose layouts need offsets past a byte), with a leaf above the shared-out levels.
TEST(LeafAlignment, TwoThreadsLayOutTheSlotsOfOne) {
  SahConfig small_leaves;
  small_leaves.max_leaf = 6;
  small_leaves.leaf_block = 1;
  small_leaves.split_budget = 0;
  const BinaryBvh built = build_binned_sah(test::random_soup(30000, 0.02f, 21), small_leaves);
  const int threads = omp_get_max_threads();
  for (const BinaryBvh& tree : {built, with_leaf_beside(built, 5)}) {
    ASSERT_GE(tree.nodes.size(), kParallelAlignNodes) << "too small to share out";
    for (uint32_t step : {4u, 16u, 512u}) {
      BinaryBvh one = tree, two = tree;
      omp_set_num_threads(1);
      align_leaves(one, step);
      omp_set_num_threads(2);
      align_leaves(two, step);
      omp_set_num_threads(threads);
      EXPECT_EQ(one.order, two.order) << "step " << step;
      EXPECT_EQ(two.order.capacity(), two.order.size());
      EXPECT_EQ(leaf_contents(two), leaf_contents(tree)) << "step " << step;
      for (std::size_t k = 0; k < tree.nodes.size(); ++k)
        ASSERT_EQ(one.nodes[k].first, two.nodes[k].first) << "node " << k << ", step " << step;
      if (step == 512) {
        EXPECT_EQ(padding_slots(two), padding_with_swaps(tree, 0, step));  // tree order
      }
    }
  }
}

TEST(LeafAlignment, PaddingSlotsBecomeZeroAreaSlotsWithoutId) {
  const TriangleMesh mesh = test::random_soup(500, 0.05f, 9);
  BinaryBvh tree = build_binned_sah(mesh);
  align_leaves(tree, 16);
  const TriangleSoA soa(mesh, tree.order);
  const WideBvh wide(tree, 8);
  ASSERT_EQ(soa.size(), tree.order.size());
  for (uint32_t s = 0; s < soa.size(); ++s) {
    if (tree.order[s] != TriangleSoA::kPaddingSlot) {
      ASSERT_EQ(soa.id(s), int32_t(tree.order[s]));
      continue;
    }
    ASSERT_EQ(soa.id(s), -1) << "slot " << s;
    const Vec3f a = soa.v0(s), b = soa.v1(s), c = soa.v2(s);
    ASSERT_TRUE(a.x == 0 && a.y == 0 && a.z == 0 && b.x == 0 && c.z == 0) << "slot " << s;
  }
  EXPECT_EQ(wide.leaf_count(), leaf_contents(tree).size());
}

// The default node width (bvh_traversal.h): 16 on the SIMD ISAs for deep trees, and on Intel's AVX-512
// for every tree, 8 otherwise; and a BvhAccelerator's leaves take the fewest steps of its kernel.
TEST(LeafAlignment, BvhDefaultsToSixteenWideNodesForLargeMeshesAndIntelAvx512) {
  for (const char* amd_or_other : {"AuthenticAMD", "HygonGenuine", ""}) {
    EXPECT_EQ(default_bvh_width(Isa::avx512, kWideNodeTriangles, amd_or_other), 16);
    EXPECT_EQ(default_bvh_width(Isa::avx512, kWideNodeTriangles - 1, amd_or_other), 8);
  }
  EXPECT_EQ(default_bvh_width(Isa::avx512, 1, "GenuineIntel"), 16);
  EXPECT_EQ(default_bvh_width(Isa::avx512, kWideNodeTriangles, "GenuineIntel"), 16);
  for (const char* vendor : {"AuthenticAMD", "GenuineIntel"}) {
    EXPECT_EQ(default_bvh_width(Isa::avx2, kWideNodeTriangles, vendor), 16);
    EXPECT_EQ(default_bvh_width(Isa::avx2, kWideNodeTriangles - 1, vendor), 8);
    EXPECT_EQ(default_bvh_width(Isa::scalar, 1u << 20, vendor), 8);
  }
  EXPECT_EQ(default_bvh_width(Isa::avx512, 100),
            default_bvh_width(Isa::avx512, 100, cpu_features().vendor));  // this CPU's vendor
  if (!isa_supported(Isa::avx512))
    GTEST_SKIP() << "no AVX-512 on this CPU: the built-BvhAccelerator half is skipped";
  const TriangleMesh big = test::random_soup(int(kWideNodeTriangles), 0.01f, 3);
  BvhOptions unmerged;  // merged leaves join several leaves' steps
  unmerged.merge_steps = 0;
  const BvhAccelerator bvh(big, TraceConfig{Isa::avx512, Intersector::mt}, unmerged);
  EXPECT_EQ(bvh.tree().width(), 16);
  test::for_each_leaf(bvh.tree(), [&](uint32_t begin, uint32_t count) {
    EXPECT_EQ(steps(begin, count, 16), steps(0, count, 16)) << "leaf at slot " << begin;
  });
}

// The most slots in one leaf of a wide tree.
uint32_t largest_leaf(const WideBvh& tree) {
  uint32_t largest = 0;
  test::for_each_leaf(tree, [&](uint32_t, uint32_t count) { largest = std::max(largest, count); });
  return largest;
}

// Leaves of one kernel step for small meshes, two for large ones and the scalar ISA
// (bvh_traversal.h); a BvhAccelerator's unmerged leaves keep to the rule, or to BvhOptions::leaf_steps,
// on every SIMD ISA the CPU has.
TEST(LeafAlignment, SmallMeshesHoldOneKernelStepPerLeaf) {
  for (const Isa isa : {Isa::avx2, Isa::avx512}) {
    EXPECT_EQ(default_leaf_steps(isa, 100), 1);
    EXPECT_EQ(default_leaf_steps(isa, kWideNodeTriangles - 1), 1);
    EXPECT_EQ(default_leaf_steps(isa, kWideNodeTriangles), 2);
  }
  EXPECT_EQ(default_leaf_steps(Isa::scalar, 100), 2);
  const TriangleMesh soup = test::random_soup(4000, 0.01f, 5);
  const TriangleMesh big = test::random_soup(int(kWideNodeTriangles), 0.01f, 3);
  for (const Isa isa : {Isa::avx2, Isa::avx512}) {
    if (!isa_supported(isa)) {
      std::printf("skipped ISA %s: not on this CPU\n", isa_name(isa));
      continue;
    }
    BvhOptions unmerged;
    unmerged.merge_steps = 0;
    const BvhAccelerator bvh(soup, TraceConfig{isa, Intersector::mt}, unmerged);
    const uint32_t block = isa == Isa::avx512 ? 16 : 8;
    EXPECT_EQ(bvh.leaf_steps(), 1) << isa_name(isa);
    EXPECT_LE(largest_leaf(bvh.tree()), block) << isa_name(isa);
    EXPECT_GT(largest_leaf(bvh.tree()), 1u) << isa_name(isa);
    for (const int steps : {1, 2}) {
      BvhOptions given = unmerged;
      given.leaf_steps = steps;
      const BvhAccelerator large(big, TraceConfig{isa, Intersector::mt}, given);
      EXPECT_EQ(large.leaf_steps(), steps) << isa_name(isa);
      EXPECT_LE(largest_leaf(large.tree()), uint32_t(steps) * block) << isa_name(isa) << ", " << steps;
      EXPECT_GT(largest_leaf(large.tree()), uint32_t(steps - 1) * block) << isa_name(isa) << ", " << steps;
    }
    const BvhAccelerator by_default(big, TraceConfig{isa, Intersector::mt}, unmerged);
    EXPECT_EQ(by_default.leaf_steps(), default_leaf_steps(isa, big.size())) << isa_name(isa);
  }
}

}  // namespace
}  // namespace rayvec
