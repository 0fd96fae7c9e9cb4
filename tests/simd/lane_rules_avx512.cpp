// lane_rules.h for avx512: next_up, mt_lower and the packet hull over vfloat, compiled with
// AVX-512's flags.
#include <cstdint>

#include "kernels/triangle_kernels.h"
#include "simd/vfloat_avx512.h"
#include "bvh/simd/packet_lanes_avx512.h"
#include "lane_rules.h"

namespace rayvec::avx512 {

#include "kernels/moller_trumbore.inl"
#include "kernels/mt_float.inl"

using PacketFloat = vfloat;
#include "lane_rules.inl"

}  // namespace rayvec::avx512

rayvec::test::LaneRules rayvec::test::lane_rules_avx512() {
  return {&avx512::next_up_lanes, &avx512::mt_lower_lanes, &avx512::packet_hull_lanes,
          &avx512::det_sign_forms_lanes};
}
