// Counting traversal: the closest-hit and any-hit queries of the scalar single-ray traversal
// (bvh/single_ray_traversal.inl) instantiated with policies that count the work — the nodes whose
// child boxes are tested and the triangle slots the leaves test. For the cost AOV and teaching
// only: the hot traversals of every ISA stay uncounted, and this one counts what the scalar
// traversal does over the same tree (the same nodes in the same order as the ISA's single-ray
// traversal, whose ordering rule is the same; the packet traversal of camera rays visits nodes per
// packet instead). Same hits as the uncounted traversal.
#pragma once
#include <cstdint>

#include "bvh/wide_bvh.h"
#include "kernels/triangle_kernels.h"

namespace rayvec {

struct TraversalCost {
  uint64_t nodes = 0;      // inner nodes whose child boxes were tested
  uint64_t triangles = 0;  // triangle slots tested in leaves (a leaf's whole slot range)

  TraversalCost& operator+=(const TraversalCost& o) {
    nodes += o.nodes;
    triangles += o.triangles;
    return *this;
  }
};

namespace scalar {
// As BvhTraversal::closest / occluded over a tree of any width (4, 8 or 16), adding to `cost`.
// Thread-safe (per-thread counting state).
void counted_closest(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                     const Ray& ray, Hit& hit, TraversalCost& cost);
bool counted_occluded(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                      const Ray& ray, const HitFilter* filter, TraversalCost& cost);
}  // namespace scalar

}  // namespace rayvec
