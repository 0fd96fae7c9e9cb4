// The variant traversal of bvh_bench (trv=1; closest and any hit): the .inl named by
// -DRV_VARIANT_INL (by default the tree's own bvh_traversal.inl) compiled as an AVX-512 unit, 8- or
// 16-wide nodes.
#include <cstdint>

#include "bvh/bvh_kernels.h"
#include "kernels/simd/box_lanes_avx512.h"

#ifndef RV_VARIANT_INL
#define RV_VARIANT_INL "bvh/bvh_traversal.inl"
#endif

namespace rayvec::avx512::variant_unit {
#include RV_VARIANT_INL
}  // namespace rayvec::avx512::variant_unit

namespace rayvec::variant {
void closest(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
             const Ray& ray, Hit& hit) {
  if (bvh.width == 16) avx512::variant_unit::bvh_closest<avx512::BoxLanes16>(bvh, tris, kernels, ray, hit);
  else avx512::variant_unit::bvh_closest<avx512::BoxLanes8>(bvh, tris, kernels, ray, hit);
}
bool occluded(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
              const Ray& ray) {
  if (bvh.width == 16) return avx512::variant_unit::bvh_occluded<avx512::BoxLanes16>(bvh, tris, kernels, ray, nullptr);
  return avx512::variant_unit::bvh_occluded<avx512::BoxLanes8>(bvh, tris, kernels, ray, nullptr);
}
}  // namespace rayvec::variant
