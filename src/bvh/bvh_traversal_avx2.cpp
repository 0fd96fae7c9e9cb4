// Instantiates the wide-BVH traversal (single_ray_traversal.inl) for avx2. Thin on purpose: the traversal
// body is shared; only the box-lanes type and the compile flags (cmake/IsaFlags.cmake) differ.
#include <cstdint>

#include "bvh/bvh_traversal.h"
#include "kernels/triangle_kernels.h"
#include "simd/vfloat_avx2.h"
#include "bvh/simd/box_lanes_avx2.h"
#include "bvh/simd/packet_lanes_avx2.h"

namespace rayvec::avx2 {

constexpr Isa kThisIsa = Isa::avx2;

#include "bvh/single_ray_traversal.inl"
#include "kernels/moller_trumbore.inl"
#include "kernels/watertight.inl"
#include "bvh/packet_leaf.inl"
#include "bvh/watertight_packet_leaf.inl"
#include "bvh/packet_traversal.inl"

namespace {
// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const BvhTraversal k8{Isa::avx2,
                                8,
                                &bvh_closest<BoxLanes8>,
                                &bvh_occluded<BoxLanes8>,
                                &bvh_closest_packet<BoxLanes8, PacketLanes8>,
                                8};
constinit const BvhTraversal k16{Isa::avx2,
                                 16,
                                 &bvh_closest<BoxLanes16>,
                                 &bvh_occluded<BoxLanes16>,
                                 &bvh_closest_packet<BoxLanes16, PacketLanes8>,
                                 8};
}  // namespace

const BvhTraversal* bvh_traversal(int width, bool /*direct_leaf: AVX-512 only*/) {
  switch (width) {
    case 8: return &k8;
    case 16: return &k16;
    default: return nullptr;
  }
}

}  // namespace rayvec::avx2
