// Instantiates the wide-BVH traversal (single_ray_traversal.inl) for avx512. Thin on purpose: the traversal
// body is shared; only the box-lanes type and the compile flags (cmake/IsaFlags.cmake) differ.
#include <cstdint>

#include "bvh/bvh_traversal.h"
#include "kernels/triangle_kernels.h"
#include "simd/vfloat_avx512.h"
#include "bvh/simd/box_lanes_avx512.h"
#include "bvh/simd/packet_lanes_avx512.h"

namespace rayvec::avx512 {

constexpr Isa kThisIsa = Isa::avx512;

#include "bvh/single_ray_traversal.inl"
#include "kernels/moller_trumbore.inl"
#include "kernels/mt_float.inl"
#include "kernels/mt_float_rays.inl"
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
// The closest-hit traversal's leaves by this unit's float `mt` kernel, called directly (not
// through the table, around whose indirect call the traversal's ray registers are saved) when the
// table is that kernel's; other tables through the table. The rays reaching a leaf are finite
// (bvh.cpp rejects the others), so skipping the table entry's finite_ray test changes nothing.
// Any hit: MtAnyHitLeaf (bvh/mt_any_hit_leaf.inl) in every table, whatever the closest-hit choice
// (the once-per-ray any-hit setup gained on AVX-512 as on AVX2:
// benchmarks.md#decision-any-hit-leaf-lanes).
struct DirectMtLeaf {
  struct Closest : LeafRay {
    using LeafRay::LeafRay;
    RAYVEC_INLINE void closest(const TriangleArrays& tris, uint32_t begin, uint32_t end, Hit& hit) const {
      if (k.intersector != Intersector::mt || k.isa != kThisIsa) return k.closest(tris, begin, end, ray, hit);
      if (ray.tmin == 0.0f)
        closest_mt_float_rays<vfloat, true, 1>(tris, begin, end, &ray, &hit);
      else
        closest_mt_float_rays<vfloat, false, 1>(tris, begin, end, &ray, &hit);
    }
  };
  using AnyHit = MtAnyHitLeaf<vfloat>;
};

// The any-hit leaf of the tables whose closest-hit leaves go through the table: the float `mt`
// kernel called directly whatever the closest-hit choice (benchmarks.md#decision-any-hit-leaf-lanes).
using TableAnyHitLeaf = DirectMtLeaf;
}  // namespace

#include "bvh/traversal_tables.inl"

}  // namespace rayvec::avx512
