// Instantiates the wide-BVH traversal (single_ray_traversal.inl) for scalar. Thin on purpose: the traversal
// body is shared; only the box-lanes type and the compile flags (cmake/IsaFlags.cmake) differ.
#include <cstdint>

#include "bvh/bvh_traversal.h"
#include "bvh/simd/box_lanes_scalar.h"

namespace rayvec::scalar {

#include "bvh/single_ray_traversal.inl"

namespace {
// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const BvhTraversal k4{Isa::scalar, 4, &bvh_closest<BoxLanes4>, &bvh_occluded<BoxLanes4>, nullptr,
                                nullptr,     0};
constinit const BvhTraversal k8{Isa::scalar, 8, &bvh_closest<BoxLanes8>, &bvh_occluded<BoxLanes8>, nullptr,
                                nullptr,     0};
}  // namespace

const BvhTraversal* bvh_traversal(int width, LeafCall /*none but the table on the scalar ISA*/, Intersector) {
  switch (width) {
    case 4: return &k4;
    case 8: return &k8;
    default: return nullptr;
  }
}

}  // namespace rayvec::scalar
