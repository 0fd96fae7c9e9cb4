// Leaf alignment: places the leaves of a BinaryBvh so that each takes as few steps of the triangle
// kernel as its size needs. The kernels step through aligned groups of `step` slots (TriangleSoA's
// rows are blocked, triangle_soa.h), masking lanes outside the leaf: a leaf that fits in what is
// left of the current step starts there, sharing the step with the leaf before it; otherwise it
// starts on the next multiple of `step`. The gaps become padding slots (TriangleSoA::kPaddingSlot:
// zero area, id −1) that no binary leaf covers (a merged leaf of the wide BVH may: wide_bvh.h).
// Of the two children of each inner node, the one laid out first is the one that leaves the fewest
// padding slots in the whole tree (benchmarks.md#decision-leaf-alignment).
#pragma once
#include <cstddef>
#include <cstdint>

#include "bvh/binary_bvh.h"

namespace rayvec {

// Trees of fewer nodes are aligned on the calling thread, larger ones by all the threads OpenMP
// allows: sharing out a walk of a few hundred µs would cost more than it saves.
constexpr std::size_t kParallelAlignNodes = std::size_t(1) << 14;

// Rewrites tree.order (inserting kPaddingSlot entries) and every leaf's `first` so each leaf of
// n triangles lies in ceil(n / step) aligned groups of `step` slots (a power of two; 1 leaves the
// tree unchanged). Leaves keep their triangles, in their order; every subtree's leaves stay
// contiguous (with padding between them), but two sibling subtrees may trade places. The result
// does not depend on the number of threads.
void align_leaves(BinaryBvh& tree, uint32_t step);

}  // namespace rayvec
