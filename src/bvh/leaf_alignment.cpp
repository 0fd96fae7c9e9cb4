#include "bvh/leaf_alignment.h"

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

// What laying out a subtree costs, for every offset (mod step) at which its first slot could start:
// the padding slots inside it and the offset after its last slot. A stack of them, `step` entries
// each, flat (one pair of vectors for the whole walk, no copies of whole layouts).
struct LayoutStack {
  std::vector<uint32_t> padding;
  std::vector<uint8_t> exit;
  void push_leaf(uint32_t count, uint32_t step) {
    for (uint32_t o = 0; o < step; ++o) {
      const uint32_t pad = leaf_padding(o, count, step);
      padding.push_back(pad);
      exit.push_back(uint8_t((o + pad + count) & (step - 1)));
    }
  }
};

// Which child of each inner binary node is laid out first, chosen per entry offset (bit o set: the
// second child first when the node starts at offset o) so that the whole tree needs the fewest
// padding slots. Swapping two subtrees keeps every subtree's slots contiguous, which merged leaves
// of the wide BVH rely on; exact by dynamic programming over the offset, the only state one
// subtree's layout passes to the next. Post-order without recursion (the tree may be deep); only
// the layouts of the open path are alive.
struct ChildOrder {
  std::vector<uint64_t> second_first;  // per node, bit o: lay out the second child first at offset o
  uint32_t padding = 0;                // padding slots of the whole tree laid out from offset 0
};
ChildOrder second_child_first(const BinaryBvh& tree, uint32_t step) {
  std::vector<uint64_t> swap(tree.nodes.size(), 0);
  std::vector<std::pair<uint32_t, bool>> stack{{0, false}};
  LayoutStack done;  // layouts of finished subtrees whose parent is still open
  uint32_t pad[kMaxReorderStep];
  uint8_t out[kMaxReorderStep];
  while (!stack.empty()) {
    const auto [k, children_done] = stack.back();
    stack.pop_back();
    const BinaryNode& n = tree.nodes[k];
    if (n.leaf()) {
      done.push_leaf(n.count, step);
      continue;
    }
    if (!children_done) {
      stack.push_back({k, true});
      stack.push_back({n.first + 1, false});
      stack.push_back({n.first, false});
      continue;
    }
    const std::size_t b = done.padding.size() - step, a = b - step;  // second child, first child
    const uint32_t* pa = &done.padding[a];
    const uint32_t* pb = &done.padding[b];
    const uint8_t* ea = &done.exit[a];
    const uint8_t* eb = &done.exit[b];
    for (uint32_t o = 0; o < step; ++o) {
      const uint32_t ab = pa[o] + pb[ea[o]], ba = pb[o] + pa[eb[o]];
      if (ba < ab) swap[k] |= uint64_t(1) << o;
      pad[o] = ba < ab ? ba : ab;
      out[o] = ba < ab ? ea[eb[o]] : eb[ea[o]];
    }
    std::copy(pad, pad + step, done.padding.begin() + std::ptrdiff_t(a));
    std::copy(out, out + step, done.exit.begin() + std::ptrdiff_t(a));
    done.padding.resize(b);
    done.exit.resize(b);
  }
  return {std::move(swap), done.padding[0]};  // the root's layout, from offset 0
}

}  // namespace

void align_leaves(BinaryBvh& tree, uint32_t step) {
  if (step <= 1 || tree.nodes.empty()) return;
  const ChildOrder chosen = step <= kMaxReorderStep
                                ? second_child_first(tree, step)
                                : ChildOrder{std::vector<uint64_t>(tree.nodes.size(), 0), 0};
  const std::vector<uint64_t>& swap = chosen.second_first;
  std::vector<uint32_t> order;
  order.reserve(tree.order.size() + chosen.padding);  // exact when the order was chosen
  // depth first, each node's children in the chosen order
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const uint32_t k = stack.back();
    stack.pop_back();
    BinaryNode& n = tree.nodes[k];
    const auto offset = uint32_t(order.size() & (step - 1));
    if (!n.leaf()) {
      const bool second_first = (swap[k] >> offset) & 1;
      stack.push_back(second_first ? n.first : n.first + 1);
      stack.push_back(second_first ? n.first + 1 : n.first);
      continue;
    }
    order.insert(order.end(), leaf_padding(offset, n.count, step), TriangleSoA::kPaddingSlot);
    const auto first = n.first;
    n.first = uint32_t(order.size());
    order.insert(order.end(), tree.order.begin() + first, tree.order.begin() + first + n.count);
  }
  tree.order = std::move(order);
}

}  // namespace rayvec
