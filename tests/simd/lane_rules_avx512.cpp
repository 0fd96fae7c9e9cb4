// lane_rules.h for avx512: next_up and mt_lower over vfloat, compiled with AVX-512's flags.
#include <cstdint>

#include "kernels/triangle_kernels.h"
#include "simd/vfloat_avx512.h"
#include "lane_rules.h"

namespace rayvec::avx512 {

#include "kernels/moller_trumbore.inl"
#include "kernels/mt_float.inl"

namespace {
template <class V>
void next_up_all(const float* in, float* out, int n) {
  for (int i = 0; i < n; i += V::W) next_up(V::load(in + i)).store(out + i);
}
void next_up_lanes(const float* in, float* out, int n) { next_up_all<vfloat>(in, out, n); }
void mt_lower_lanes(const float* in, float* out, int n) {
  for (int i = 0; i < n; i += vfloat::W) mt_lower(vfloat::load(in + i)).store(out + i);
}
}  // namespace

}  // namespace rayvec::avx512

rayvec::test::LaneRules rayvec::test::lane_rules_avx512() {
  return {&avx512::next_up_lanes, &avx512::mt_lower_lanes};
}
