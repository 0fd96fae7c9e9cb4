// The lane forms of the packets' per-lane rules, from each ISA's units (lane_rules_<isa>.cpp, compiled
// with that ISA's flags): next_up (simd/vfloat_<isa>.h, and VPair's of simd/vfloat_pair.inl on AVX2)
// and mt_lower (kernels/mt_float.inl), applied to n values, n a multiple of 16; and the hull of a
// uniform forward packet (PacketForward::hull, bvh/simd/packet_lanes.inl) beside the lanes it bounds;
// and the two forms in which the one-origin group test orients its values by det's sign.
#pragma once

namespace rayvec::test {

// A packet's hull and its lanes: hull = nr_lo, nr_hi, fr_lo, fr_hi, kn_hi, kf_lo (three axes each),
// tmin (lowest) and tmax (highest) over the lanes asked for; lanes = every lane's nr, fr, kn, kf
// (three rows each), tmin and tmax.
struct PacketHullLanes {
  float hull[20];
  float lanes[14][16];
};

struct LaneRules {
  void (*next_up)(const float* in, float* out, int n);
  void (*mt_lower)(const float* in, float* out, int n);
  // soa: 8 rows of 16 lanes (o, 1/d, tmin, tmax; one direction sign per axis over `lanes`)
  void (*packet_hull)(const float* soa, unsigned lanes, float eps, PacketHullLanes* out);
  // The one-origin group test's two forms of det's orientation (kernels/mt_float_rays.inl) for
  // lanes x[i], det[i] and one slack: out rows 0..5 = fused u, flipped u, fused v, flipped v, fused
  // t·det + 0, flipped t·det + 0 (fnmadd(s, x, slack), slack − xor_sign(x, det), fmadd(s, x, slack),
  // xor_sign(x, det) + slack, fmadd(s, x, 0), xor_sign(x, det) + 0, s = sign_one(det)); n values.
  void (*det_sign_forms)(const float* x, const float* det, float slack, float* out, int n);
};

LaneRules lane_rules_avx2();
LaneRules lane_rules_avx512();

}  // namespace rayvec::test
