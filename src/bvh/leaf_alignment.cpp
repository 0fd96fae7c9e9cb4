#include "bvh/leaf_alignment.h"

#include <omp.h>

#include <algorithm>
#include <bit>
#include <utility>
#include <vector>

#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

// Kernel steps covering `count` slots from `first`: the kernels step through aligned groups of
// `step` slots (a power of two), masking the lanes outside the leaf.
uint32_t steps_from(uint32_t first, uint32_t count, uint32_t step) {
  return ((first & (step - 1)) + count + step - 1) >> std::countr_zero(step);
}

// The padding a leaf of `count` slots needs when it would start at `offset` (mod step): none if it
// fits in as many steps from there as from a step's start, else up to the next step.
uint32_t leaf_padding(uint32_t offset, uint32_t count, uint32_t step) {
  return steps_from(offset, count, step) > steps_from(0, count, step) ? (step - offset) & (step - 1) : 0;
}

constexpr uint32_t kMaxReorderStep = 64;  // a node's choices are one bit per entry offset

constexpr unsigned kSubtreesPerThread = 8;  // the cut's subtrees differ in size: many even the load

// What laying out a subtree costs, for every offset (mod step) at which its first slot could start:
// the padding slots inside it and the offset after its last slot. A stack of them, `step` entries
// each, flat (one pair of vectors for the whole walk, no copies of whole layouts).
struct LayoutStack {
  std::vector<uint32_t> padding;
  std::vector<uint32_t> exit;
  std::vector<uint32_t> joined_padding, joined_exit;  // join()'s result, before it replaces its inputs
  uint32_t triangles = 0;                             // in the leaves push_leaf pushed

  void push_leaf(uint32_t count, uint32_t step) {
    for (uint32_t o = 0; o < step; ++o) {
      const uint32_t pad = leaf_padding(o, count, step);
      padding.push_back(pad);
      exit.push_back((o + pad + count) & (step - 1));
    }
    triangles += count;
  }
  // Pushes the layout `from` holds (a finished subtree's: `step` entries).
  void push(const LayoutStack& from) {
    padding.insert(padding.end(), from.padding.begin(), from.padding.end());
    exit.insert(exit.end(), from.exit.begin(), from.exit.end());
  }
  // Replaces the top two layouts (a node's first child, then its second) by the node's: at each
  // entry offset the order of the two that needs less padding (the first child first on a tie, or
  // always when !reorder). Returns the choices: bit o set where the second child goes first.
  uint64_t join(uint32_t step, bool reorder) {
    const std::size_t b = padding.size() - step, a = b - step;
    joined_padding.resize(step);
    joined_exit.resize(step);
    uint64_t second_first = 0;
    for (uint32_t o = 0; o < step; ++o) {
      const uint32_t ab = padding[a + o] + padding[b + exit[a + o]];
      const uint32_t ba = padding[b + o] + padding[a + exit[b + o]];
      const bool swap = reorder && ba < ab;
      if (swap) second_first |= uint64_t(1) << o;
      joined_padding[o] = swap ? ba : ab;
      joined_exit[o] = swap ? exit[a + exit[b + o]] : exit[b + exit[a + o]];
    }
    std::copy(joined_padding.begin(), joined_padding.end(), padding.begin() + std::ptrdiff_t(a));
    std::copy(joined_exit.begin(), joined_exit.end(), exit.begin() + std::ptrdiff_t(a));
    padding.resize(b);
    exit.resize(b);
    return second_first;
  }
};

// Whether a node of these choices (LayoutStack::join) lays out its second child first at `offset`;
// steps too wide to reorder have offsets past the choices' bits and keep the tree's order.
bool second_child_first(uint64_t choices, uint32_t offset) {
  return offset < kMaxReorderStep && ((choices >> offset) & 1) != 0;
}

// The roots of the subtrees the work is shared out by, in depth-first order (first child first):
// the nodes `depth` levels below the root, and the leaves above that. Depth 0: the root alone.
std::vector<uint32_t> subtree_roots(const BinaryBvh& tree, int depth) {
  std::vector<uint32_t> roots;
  std::vector<std::pair<uint32_t, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [k, d] = stack.back();
    stack.pop_back();
    const BinaryNode& n = tree.nodes[k];
    if (n.leaf() || d == depth) {
      roots.push_back(k);
      continue;
    }
    stack.push_back({n.first + 1, d + 1});
    stack.push_back({n.first, d + 1});
  }
  return roots;
}

// Which child of each inner binary node is laid out first, chosen per entry offset (bit o set: the
// second child first when the node starts at offset o) so that the whole tree needs the fewest
// padding slots. Swapping two subtrees keeps every subtree's slots contiguous, which merged leaves
// of the wide BVH rely on; exact by dynamic programming over the offset, the only state one
// subtree's layout passes to the next. Post-order without recursion (the tree may be deep); only
// the layouts of the open path are alive.
//
// Walks the subtree of `root`, writes the choices of its inner nodes into `swap` and pushes its
// layout onto `out`. The subtrees rooted at `done` (in depth-first order, their layouts in
// `done_layouts`) are not entered.
void choose_child_order(const BinaryBvh& tree, uint32_t root, uint32_t step,
                        const std::vector<uint32_t>& done, const std::vector<LayoutStack>& done_layouts,
                        std::vector<uint64_t>& swap, LayoutStack& out) {
  const bool reorder = step <= kMaxReorderStep;
  std::size_t next_done = 0;
  std::vector<std::pair<uint32_t, bool>> stack{{root, false}};
  while (!stack.empty()) {
    const auto [k, children_done] = stack.back();
    stack.pop_back();
    const BinaryNode& n = tree.nodes[k];
    if (next_done < done.size() && done[next_done] == k) {
      out.push(done_layouts[next_done++]);
    } else if (n.leaf()) {
      out.push_leaf(n.count, step);
    } else if (!children_done) {
      stack.push_back({k, true});
      stack.push_back({n.first + 1, false});
      stack.push_back({n.first, false});
    } else {
      swap[k] = out.join(step, reorder);
    }
  }
}

// Lays the subtree of `root` out from `out` onwards (`out - base`: its slot), each inner node's
// children in the order chosen for the offset it starts at; sets its leaves' `first`, which index
// `from` until then.
void lay_out(BinaryBvh& tree, uint32_t root, uint32_t step, const std::vector<uint64_t>& swap,
             const std::vector<uint32_t>& from, uint32_t* base, uint32_t* out) {
  std::vector<uint32_t> stack{root};
  while (!stack.empty()) {
    const uint32_t k = stack.back();
    stack.pop_back();
    BinaryNode& n = tree.nodes[k];
    const auto offset = uint32_t(std::size_t(out - base) & (step - 1));
    if (!n.leaf()) {
      const bool second_first = second_child_first(swap[k], offset);
      stack.push_back(second_first ? n.first : n.first + 1);
      stack.push_back(second_first ? n.first + 1 : n.first);
      continue;
    }
    out = std::fill_n(out, leaf_padding(offset, n.count, step), TriangleSoA::kPaddingSlot);
    const uint32_t first = n.first;
    n.first = uint32_t(out - base);
    out = std::copy_n(from.begin() + first, n.count, out);
  }
}

}  // namespace

// The threads share the work by subtrees a few levels below the root: a subtree's choices need
// nothing from outside it, the levels above need only the subtrees' layouts, and once those levels
// have chosen, the subtrees' first slots follow and each subtree lays itself out.
void align_leaves(BinaryBvh& tree, uint32_t step) {
  if (step <= 1 || tree.nodes.empty()) return;
  const int threads = tree.nodes.size() >= kParallelAlignNodes ? omp_get_max_threads() : 1;
  const int depth = threads > 1 ? std::bit_width(unsigned(threads) * kSubtreesPerThread - 1) : 0;
  const std::vector<uint32_t> roots = subtree_roots(tree, depth);
  std::vector<uint64_t> swap(tree.nodes.size(), 0);
  std::vector<LayoutStack> subtrees(roots.size());
#pragma omp parallel for schedule(dynamic, 1) if (roots.size() > 1)
  for (std::size_t i = 0; i < roots.size(); ++i)
    choose_child_order(tree, roots[i], step, {}, {}, swap, subtrees[i]);
  LayoutStack whole;
  choose_child_order(tree, 0, step, roots, subtrees, swap, whole);
  // the subtrees' first slots: the levels above them, walked in the chosen order
  std::vector<std::size_t> start(roots.size());
  std::size_t slots = 0;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const uint32_t k = stack.back();
    stack.pop_back();
    const auto offset = uint32_t(slots & (step - 1));
    const auto i = std::size_t(std::find(roots.begin(), roots.end(), k) - roots.begin());
    if (i < roots.size()) {
      start[i] = slots;
      slots += subtrees[i].triangles + subtrees[i].padding[offset];
      continue;
    }
    const BinaryNode& n = tree.nodes[k];
    const bool second_first = second_child_first(swap[k], offset);
    stack.push_back(second_first ? n.first : n.first + 1);
    stack.push_back(second_first ? n.first + 1 : n.first);
  }
  std::vector<uint32_t> order(slots);  // == tree.order.size() + whole.padding[0]
#pragma omp parallel for schedule(dynamic, 1) if (roots.size() > 1)
  for (std::size_t i = 0; i < roots.size(); ++i)
    lay_out(tree, roots[i], step, swap, tree.order, order.data(), order.data() + start[i]);
  tree.order = std::move(order);
}

}  // namespace rayvec
