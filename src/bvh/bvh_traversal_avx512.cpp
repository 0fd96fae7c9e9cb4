// Instantiates the wide-BVH traversal (bvh_traversal.inl) for avx512. Thin on purpose: the traversal
// body is shared; only the box-lanes type and the compile flags (cmake/IsaFlags.cmake) differ.
#include <cstdint>

#include "bvh/bvh_kernels.h"
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx512.h"
#include "kernels/simd/box_lanes_avx512.h"
#include "kernels/simd/packet_lanes_avx512.h"

namespace rayvec::avx512 {

constexpr Isa kThisIsa = Isa::avx512;

#include "bvh/bvh_traversal.inl"
#include "kernels/moller_trumbore.inl"
#include "kernels/mt_packet.inl"
#include "bvh/bvh_packet.inl"

namespace {
// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const BvhKernels k8{Isa::avx512, 8, &bvh_closest<BoxLanes8>, &bvh_occluded<BoxLanes8>,
                              &bvh_closest_packet<BoxLanes8, PacketLanes16>, 16};
constinit const BvhKernels k16{Isa::avx512, 16, &bvh_closest<BoxLanes16>, &bvh_occluded<BoxLanes16>,
                               &bvh_closest_packet<BoxLanes16, PacketLanes16>, 16};
}  // namespace

const BvhKernels* bvh_kernels(int width) {
  switch (width) {
    case 8: return &k8;
    case 16: return &k16;
    default: return nullptr;
  }
}

}  // namespace rayvec::avx512
