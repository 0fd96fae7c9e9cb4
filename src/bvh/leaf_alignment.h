// Leaf alignment: moves every leaf of a BinaryBvh to start on a multiple of the triangle kernel's
// SIMD width, so that a leaf's first step loads its own triangles instead of a masked step that
// begins in the previous leaf (TriangleSoA's rows are blocked, triangle_soa.h). The gaps become
// padding slots (TriangleSoA::kPaddingSlot: zero area, id −1) that no leaf range covers.
#pragma once
#include <cstdint>

#include "bvh/binary_bvh.h"

namespace rayvec {

// Rewrites tree.order (inserting kPaddingSlot entries) and every leaf's `first` so each leaf
// begins at a multiple of `step` (a power of two; 1 leaves the tree unchanged). Leaves keep their
// triangles and their order.
void align_leaves(BinaryBvh& tree, uint32_t step);

}  // namespace rayvec
