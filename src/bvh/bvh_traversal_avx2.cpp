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
#include "bvh/packet_slot_cull.inl"
#include "bvh/packet_leaf.inl"
#include "bvh/watertight_packet_leaf.inl"
#include "bvh/packet_traversal.inl"
#include "bvh/watertight_leaf.inl"
#include "bvh/mt_any_hit_leaf.inl"
#include "bvh/packet_any_hit.inl"
#include "bvh/mt_inlined_leaf.inl"

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

// The any-hit leaf of the tables whose closest-hit leaves go through the table: the table too
// (the direct any-hit kernel belongs to the direct tables).
using TableAnyHitLeaf = TableLeaf;
}  // namespace

#include "bvh/traversal_tables.inl"

}  // namespace rayvec::avx2
