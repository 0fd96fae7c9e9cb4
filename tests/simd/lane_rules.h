// The lane forms of the packets' per-lane rules, from each ISA's units (lane_rules_<isa>.cpp, compiled
// with that ISA's flags): next_up (simd/vfloat_<isa>.h, and VPair's of simd/vfloat_pair.inl on AVX2)
// and mt_lower (kernels/mt_float.inl), applied to n values, n a multiple of 16.
#pragma once

namespace rayvec::test {

struct LaneRules {
  void (*next_up)(const float* in, float* out, int n);
  void (*mt_lower)(const float* in, float* out, int n);
};

LaneRules lane_rules_avx2();
LaneRules lane_rules_avx512();

}  // namespace rayvec::test
