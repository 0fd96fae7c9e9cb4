#include "bvh/leaf_alignment.h"

#include <algorithm>
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

}  // namespace

void align_leaves(BinaryBvh& tree, uint32_t step) {
  if (step <= 1 || tree.nodes.empty()) return;
  // leaves by their position in the old order (they tile it)
  std::vector<std::pair<uint32_t, uint32_t>> leaves;  // (first, node)
  for (uint32_t k = 0; k < tree.nodes.size(); ++k)
    if (tree.nodes[k].leaf()) leaves.emplace_back(tree.nodes[k].first, k);
  std::sort(leaves.begin(), leaves.end());
  std::vector<uint32_t> order;
  order.reserve(tree.order.size() + leaves.size() * (step - 1));
  for (const auto& [first, k] : leaves) {
    BinaryNode& leaf = tree.nodes[k];
    const auto here = uint32_t(order.size());
    if (steps_from(here, leaf.count, step) > steps_from(0, leaf.count, step))
      while (order.size() % step != 0) order.push_back(TriangleSoA::kPaddingSlot);
    leaf.first = uint32_t(order.size());
    order.insert(order.end(), tree.order.begin() + first, tree.order.begin() + first + leaf.count);
  }
  tree.order = std::move(order);
}

}  // namespace rayvec
