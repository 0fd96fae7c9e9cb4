#include "bvh/leaf_alignment.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

// Kernel steps covering `count` slots from `first`: the kernels step through aligned groups of
// `step` slots, masking the lanes outside the leaf.
uint32_t steps_from(uint32_t first, uint32_t count, uint32_t step) {
  return (first % step + count + step - 1) / step;
}

// The padding a leaf of `count` slots needs when it would start at `offset` (mod step): none if it
// fits in as many steps from there as from a step's start, else up to the next step.
uint32_t leaf_padding(uint32_t offset, uint32_t count, uint32_t step) {
  return steps_from(offset, count, step) > steps_from(0, count, step) ? (step - offset) % step : 0;
}

constexpr uint32_t kMaxReorderStep = 64;  // a node's choices are one bit per entry offset

// What laying out a subtree costs, for every offset (mod step) at which its first slot could start:
// the padding slots inside it and the offset after its last slot.
struct SubtreeLayout {
  std::array<uint64_t, kMaxReorderStep> padding;
  std::array<uint8_t, kMaxReorderStep> exit;
};

SubtreeLayout leaf_layout(uint32_t count, uint32_t step) {
  SubtreeLayout s;
  for (uint32_t o = 0; o < step; ++o) {
    s.padding[o] = leaf_padding(o, count, step);
    s.exit[o] = uint8_t((o + s.padding[o] + count) % step);
  }
  return s;
}

// Which child of each inner binary node is laid out first, chosen per entry offset (bit o set: the
// second child first when the node starts at offset o) so that the whole tree needs the fewest
// padding slots. Swapping two subtrees keeps every subtree's slots contiguous, which merged leaves
// of the wide BVH rely on; exact by dynamic programming over the offset, the only state one
// subtree's layout passes to the next. Post-order without recursion (the tree may be deep); only
// the layouts of the open path are alive.
std::vector<uint64_t> second_child_first(const BinaryBvh& tree, uint32_t step) {
  std::vector<uint64_t> swap(tree.nodes.size(), 0);
  std::vector<std::pair<uint32_t, bool>> stack{{0, false}};
  std::vector<SubtreeLayout> done;  // layouts of finished subtrees whose parent is still open
  while (!stack.empty()) {
    const auto [k, children_done] = stack.back();
    stack.pop_back();
    const BinaryNode& n = tree.nodes[k];
    if (n.leaf()) {
      done.push_back(leaf_layout(n.count, step));
      continue;
    }
    if (!children_done) {
      stack.push_back({k, true});
      stack.push_back({n.first + 1, false});
      stack.push_back({n.first, false});
      continue;
    }
    const SubtreeLayout b = done.back();  // second child
    done.pop_back();
    const SubtreeLayout a = done.back();  // first child
    SubtreeLayout& s = done.back();
    for (uint32_t o = 0; o < step; ++o) {
      const uint64_t ab = a.padding[o] + b.padding[a.exit[o]];
      const uint64_t ba = b.padding[o] + a.padding[b.exit[o]];
      if (ba < ab) {
        swap[k] |= uint64_t(1) << o;
        s.padding[o] = ba;
        s.exit[o] = a.exit[b.exit[o]];
      } else {
        s.padding[o] = ab;
        s.exit[o] = b.exit[a.exit[o]];
      }
    }
  }
  return swap;
}

}  // namespace

void align_leaves(BinaryBvh& tree, uint32_t step) {
  if (step <= 1 || tree.nodes.empty()) return;
  const std::vector<uint64_t> swap =
      step <= kMaxReorderStep ? second_child_first(tree, step) : std::vector<uint64_t>(tree.nodes.size(), 0);
  std::vector<uint32_t> order;
  order.reserve(tree.order.size() + tree.order.size() / 2);
  std::vector<uint32_t> stack{0};  // depth first, each node's children in the chosen order
  while (!stack.empty()) {
    BinaryNode& n = tree.nodes[stack.back()];
    const uint32_t k = stack.back();
    stack.pop_back();
    const auto offset = uint32_t(order.size() % step);
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
