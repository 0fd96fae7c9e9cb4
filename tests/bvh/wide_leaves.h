// Test helper: every leaf of a WideBvh, whatever its node width, as the slot range it covers.
#pragma once
#include <cstdint>

#include "bvh/wide_bvh.h"

namespace rayvec::test {

// Calls f(begin, count) for each leaf reference of `tree` (count slots from slot `begin`).
template <class F>
void for_each_leaf(const WideBvh& tree, F&& f) {
  const auto visit = [&](const auto* nodes) {
    for (uint32_t n = 0; n < tree.node_count(); ++n)
      for (const uint32_t ref : nodes[n].ref)
        if (ref != kEmptyRef && (ref & kLeafFlag)) f((ref >> 5) & (kMaxLeafBegin - 1), (ref & 31) + 1);
  };
  const void* nodes = tree.arrays().nodes;
  switch (tree.width()) {
    case 4: return visit(static_cast<const WideNode<4>*>(nodes));
    case 8: return visit(static_cast<const WideNode<8>*>(nodes));
    default: return visit(static_cast<const WideNode<16>*>(nodes));
  }
}

}  // namespace rayvec::test
