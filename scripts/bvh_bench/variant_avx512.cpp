// The variant traversal of bvh_bench (trv=1; closest and any hit): the .inl named by
// -DRV_VARIANT_INL (by default the tree's own bvh_traversal.inl) compiled as an AVX-512 unit (or,
// with -DRV_AVX2, as an AVX2 unit whose functions end in _avx2: build.sh compiles both), 8- or
// 16-wide nodes.
#include <cstdint>

#include "bvh/bvh_kernels.h"
#ifdef RV_AVX2
#include "kernels/simd/box_lanes_avx2.h"
#define RV_ISA avx2
#define RV_NAME(f) f##_avx2
#else
#include "kernels/simd/box_lanes_avx512.h"
#define RV_ISA avx512
#define RV_NAME(f) f
#endif

#ifndef RV_VARIANT_INL
#define RV_VARIANT_INL "bvh/bvh_traversal.inl"
#endif

namespace rayvec::RV_ISA::variant_unit {
#include RV_VARIANT_INL
}  // namespace rayvec::RV_ISA::variant_unit

namespace rayvec::variant {
void RV_NAME(closest)(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                      const Ray& ray, Hit& hit) {
  if (bvh.width == 16) RV_ISA::variant_unit::bvh_closest<RV_ISA::BoxLanes16>(bvh, tris, kernels, ray, hit);
  else RV_ISA::variant_unit::bvh_closest<RV_ISA::BoxLanes8>(bvh, tris, kernels, ray, hit);
}
bool RV_NAME(occluded)(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                       const Ray& ray) {
  if (bvh.width == 16)
    return RV_ISA::variant_unit::bvh_occluded<RV_ISA::BoxLanes16>(bvh, tris, kernels, ray, nullptr);
  return RV_ISA::variant_unit::bvh_occluded<RV_ISA::BoxLanes8>(bvh, tris, kernels, ray, nullptr);
}
}  // namespace rayvec::variant
