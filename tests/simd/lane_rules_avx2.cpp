// lane_rules.h for avx2: next_up and the packet hull over VPair<vfloat> (the 16-lane packets'
// type, each half vfloat's) and mt_lower over vfloat, compiled with AVX2's flags.
#include <cstdint>

#include "kernels/triangle_kernels.h"
#include "simd/vfloat_avx2.h"
#include "bvh/simd/packet_lanes_avx2.h"
#include "lane_rules.h"

namespace rayvec::avx2 {

#include "kernels/moller_trumbore.inl"
#include "kernels/mt_float.inl"

using PacketFloat = VPair<vfloat>;
#include "lane_rules.inl"

}  // namespace rayvec::avx2

rayvec::test::LaneRules rayvec::test::lane_rules_avx2() {
  return {&avx2::next_up_lanes, &avx2::mt_lower_lanes, &avx2::packet_hull_lanes, &avx2::det_sign_forms_lanes};
}
