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
#include "kernels/mt_float.inl"
#include "kernels/watertight.inl"
#include "bvh/packet_leaf.inl"
#include "bvh/watertight_packet_leaf.inl"
#include "bvh/packet_traversal.inl"
#include "bvh/watertight_leaf.inl"
#include "bvh/mt_any_hit_leaf.inl"
#include "bvh/packet_any_hit.inl"

namespace {
// The traversals' leaves by this unit's float `mt` single-ray kernels, called directly (not through
// the table: the traversal's ray registers are not saved around an indirect call, and the call
// skips the table entry's finite_ray test, which the rays reaching a leaf pass: bvh.cpp rejects
// the others); other tables through the table. Same results. Any hit: MtAnyHitLeaf
// (bvh/mt_any_hit_leaf.inl).
struct DirectMtLeaf {
  static RAYVEC_INLINE bool direct(const TriangleKernels& k) {
    return k.intersector == Intersector::mt && k.isa == kThisIsa;
  }
  struct Closest : LeafRay {
    using LeafRay::LeafRay;
    RAYVEC_INLINE void closest(const TriangleArrays& tris, uint32_t begin, uint32_t end, Hit& hit) const {
      if (!direct(k)) return k.closest(tris, begin, end, ray, hit);
      if (ray.tmin == 0.0f)
        closest_mt_float_one<vfloat, true>(tris, begin, end, ray, hit);
      else
        closest_mt_float_one<vfloat, false>(tris, begin, end, ray, hit);
    }
  };
  using AnyHit = MtAnyHitLeaf<vfloat>;
};

// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const BvhTraversal k8{Isa::avx2,
                                8,
                                &bvh_closest<BoxLanes8>,
                                &bvh_occluded<BoxLanes8>,
                                &bvh_closest_packet<BoxLanes8, PacketLanes16>,
                                &bvh_occluded_packet<BoxLanes8, PacketLanes16, TableLeaf>,
                                16};
constinit const BvhTraversal k16{Isa::avx2,
                                 16,
                                 &bvh_closest<BoxLanes16>,
                                 &bvh_occluded<BoxLanes16>,
                                 &bvh_closest_packet<BoxLanes16, PacketLanes16>,
                                 &bvh_occluded_packet<BoxLanes16, PacketLanes16, TableLeaf>,
                                 16};
constinit const BvhTraversal k8_direct{Isa::avx2,
                                       8,
                                       &bvh_closest<BoxLanes8, DirectMtLeaf>,
                                       &bvh_occluded<BoxLanes8, DirectMtLeaf>,
                                       &bvh_closest_packet<BoxLanes8, PacketLanes16>,
                                       &bvh_occluded_packet<BoxLanes8, PacketLanes16, DirectMtLeaf>,
                                       16,
                                       true};
constinit const BvhTraversal k16_direct{Isa::avx2,
                                        16,
                                        &bvh_closest<BoxLanes16, DirectMtLeaf>,
                                        &bvh_occluded<BoxLanes16, DirectMtLeaf>,
                                        &bvh_closest_packet<BoxLanes16, PacketLanes16>,
                                        &bvh_occluded_packet<BoxLanes16, PacketLanes16, DirectMtLeaf>,
                                        16,
                                        true};
constinit const BvhTraversal k8_watertight{
    Isa::avx2,
    8,
    &bvh_closest<BoxLanes8, WatertightLeaf<vfloat>>,
    &bvh_occluded<BoxLanes8, WatertightLeaf<vfloat>>,
    &bvh_closest_packet<BoxLanes8, PacketLanes16>,
    &bvh_occluded_packet<BoxLanes8, PacketLanes16, WatertightLeaf<vfloat>>,
    16,
    true};
constinit const BvhTraversal k16_watertight{
    Isa::avx2,
    16,
    &bvh_closest<BoxLanes16, WatertightLeaf<vfloat>>,
    &bvh_occluded<BoxLanes16, WatertightLeaf<vfloat>>,
    &bvh_closest_packet<BoxLanes16, PacketLanes16>,
    &bvh_occluded_packet<BoxLanes16, PacketLanes16, WatertightLeaf<vfloat>>,
    16,
    true};
}  // namespace

const BvhTraversal* bvh_traversal(int width, bool direct_leaf, Intersector intersector) {
  const bool mt = direct_leaf && intersector == Intersector::mt;
  const bool watertight = direct_leaf && intersector == Intersector::watertight;
  switch (width) {
    case 8: return mt ? &k8_direct : watertight ? &k8_watertight : &k8;
    case 16: return mt ? &k16_direct : watertight ? &k16_watertight : &k16;
    default: return nullptr;
  }
}

}  // namespace rayvec::avx2
