// The scalar single-ray traversal instantiated with counting policies (counting_traversal.h): a
// box-lanes type that counts each node's box test and leaf calls that count the slots they test.
// The traversal body is not touched; the counters live in thread-local pointers set for the
// duration of one query, so the uncounted instantiations carry no trace of them.
#include <cstdint>

#include "bvh/counting_traversal.h"
#include "bvh/simd/box_lanes_scalar.h"

namespace rayvec::scalar {

#include "bvh/single_ray_traversal.inl"

namespace {

constinit thread_local TraversalCost* t_cost = nullptr;
constinit thread_local const TriangleKernels* t_kernels = nullptr;

// B's box tests, each counted as one node visit.
template <class B>
struct CountingBoxes : B {
  template <class... A>
  static RAYVEC_INLINE unsigned hits(const A&... a) {
    ++t_cost->nodes;
    return B::hits(a...);
  }
  template <class... A>
  static RAYVEC_INLINE unsigned hits_forward(const A&... a) {
    ++t_cost->nodes;
    return B::hits_forward(a...);
  }
};

struct CountingLeaf {
  struct Closest : TableLeaf::Closest {
    using TableLeaf::Closest::Closest;
    RAYVEC_INLINE void closest(const TriangleArrays& tris, uint32_t begin, uint32_t end, Hit& hit) const {
      t_cost->triangles += end - begin;
      TableLeaf::Closest::closest(tris, begin, end, hit);
    }
  };
};

bool counting_occluded_leaf(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray& ray,
                            const HitFilter* filter) {
  t_cost->triangles += end - begin;
  return t_kernels->occluded(tris, begin, end, ray, filter);
}

// Sets the thread's counting state for one query and clears it after.
struct CountingScope {
  CountingScope(TraversalCost& cost, const TriangleKernels& kernels) {
    t_cost = &cost;
    t_kernels = &kernels;
  }
  ~CountingScope() {
    t_cost = nullptr;
    t_kernels = nullptr;
  }
};

using Lanes16 = BoxLanes<vfloat, 16>;

}  // namespace

void counted_closest(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                     const Ray& ray, Hit& hit, TraversalCost& cost) {
  const CountingScope scope(cost, kernels);
  switch (bvh.width) {
    case 4: return bvh_closest<CountingBoxes<BoxLanes4>, CountingLeaf>(bvh, tris, kernels, ray, hit);
    case 8: return bvh_closest<CountingBoxes<BoxLanes8>, CountingLeaf>(bvh, tris, kernels, ray, hit);
    default: return bvh_closest<CountingBoxes<Lanes16>, CountingLeaf>(bvh, tris, kernels, ray, hit);
  }
}

bool counted_occluded(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                      const Ray& ray, const HitFilter* filter, TraversalCost& cost) {
  const CountingScope scope(cost, kernels);
  TriangleKernels counting = kernels;
  counting.occluded = &counting_occluded_leaf;
  switch (bvh.width) {
    case 4: return bvh_occluded<CountingBoxes<BoxLanes4>>(bvh, tris, counting, ray, filter);
    case 8: return bvh_occluded<CountingBoxes<BoxLanes8>>(bvh, tris, counting, ray, filter);
    default: return bvh_occluded<CountingBoxes<Lanes16>>(bvh, tris, counting, ray, filter);
  }
}

}  // namespace rayvec::scalar
