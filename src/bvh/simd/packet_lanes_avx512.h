// AVX-512 packet lanes for bvh/packet_traversal.inl: 16 rays, one per zmm lane. The box tests are
// packet_lanes.inl's over vfloat (PacketLanes16: any tmin; its Forward: tmin >= 0, one FMA a
// slab); this file adds the packet's setup (the AoS → SoA transpose of its rays) and a lane
// reduction. One of the only files that include <immintrin.h>;
// included only by *_avx512.cpp units after box_lanes_avx512.h, in namespace rayvec::avx512.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "bvh/simd/box_lanes_avx512.h"

namespace rayvec::avx512 {

#include "bvh/simd/packet_lanes.inl"

// The lane type of a packet: one zmm of 16 rays.
using pfloat = vfloat;

struct PacketLanes16 : PacketLanesBase<vfloat, PacketLanes16> {
  template <bool Uniform>
  using Forward = PacketForward<vfloat, Uniform>;

  // Transposes 16 rays of 8 floats each (the Ray layout: o, d, tmin, tmax; ray k at rays + 8k) into
  // rows[f][k], reading only the rays of `lanes` (the others' rows are 0). Returns the lanes of
  // `lanes` whose ray is traceable: finite origin and direction, tmin and tmax not NaN.
  // Two rays per load; three stages of two-register shuffles each trade one bit of the register
  // index (ray) for one bit of the lane index (field): unpacklo/hi (ray bit 0 for field bit 1),
  // shufps (ray bit 1 for field bit 0), vpermt2ps (ray bit 2 for field bit 2, putting lanes in ray
  // order) — 24 shuffles instead of 128 scalar loads and stores (and no store-forwarding stall).
  static RAYVEC_INLINE unsigned load_rays(const float* rays, unsigned lanes, float (*rows)[16]) {
    __m512 r[8], s[8];
    if (lanes == 0xffffu) {
      for (int j = 0; j < 8; ++j) r[j] = _mm512_loadu_ps(rays + 16 * j);
    } else {
      for (int j = 0; j < 8; ++j) {
        const unsigned two = (lanes >> (2 * j)) & 3u;
        const __mmask16 m = __mmask16((two & 1u ? 0x00ffu : 0u) | (two & 2u ? 0xff00u : 0u));
        r[j] = _mm512_maskz_loadu_ps(m, rays + 16 * j);
      }
    }
    for (int j = 0; j < 8; j += 2) {  // slot bit 0 becomes field bit 1
      // maskz forms: g++ 12's plain ones merge into _mm512_undefined_ps() and warn
      s[j] = _mm512_maskz_unpacklo_ps(__mmask16(0xffff), r[j], r[j + 1]);
      s[j + 1] = _mm512_maskz_unpackhi_ps(__mmask16(0xffff), r[j], r[j + 1]);
    }
    for (int j : {0, 1, 4, 5}) {  // slot bit 1 becomes field bit 0
      r[j] = _mm512_shuffle_ps(s[j], s[j + 2], 0x44);
      r[j + 2] = _mm512_shuffle_ps(s[j], s[j + 2], 0xee);
    }
    // slot bit 2 becomes field bit 2; lane (h, field bit 2, ray bits 1, 0) -> lane = ray
    const __m512i lo = _mm512_setr_epi32(0, 8, 1, 9, 2, 10, 3, 11, 16, 24, 17, 25, 18, 26, 19, 27);
    const __m512i hi = _mm512_add_epi32(lo, _mm512_set1_epi32(4));
    for (int j = 0; j < 4; ++j) {
      s[j] = _mm512_permutex2var_ps(r[j], lo, r[j + 4]);
      s[j + 4] = _mm512_permutex2var_ps(r[j], hi, r[j + 4]);
    }
    // slot (field bit 2, field bit 0, field bit 1)
    for (int f = 0; f < 8; ++f) _mm512_store_ps(rows[f], s[(f & 4) | ((f & 1) << 1) | ((f & 2) >> 1)]);
    // fpclass 0x99: QNaN, SNaN, +inf, -inf; 0x81: QNaN, SNaN
    unsigned bad = 0;
    for (int f = 0; f < 6; ++f) bad |= _mm512_fpclass_ps_mask(_mm512_load_ps(rows[f]), 0x99);
    bad |= _mm512_fpclass_ps_mask(_mm512_load_ps(rows[6]), 0x81);
    bad |= _mm512_fpclass_ps_mask(_mm512_load_ps(rows[7]), 0x81);
    return lanes & ~bad;
  }
  // The smallest of tn over `lanes` (nonzero).
  static RAYVEC_INLINE float min_lanes(const float* tn, unsigned lanes) {
    return hmin_lanes(vfloat::load(tn), lanes);
  }
};

}  // namespace rayvec::avx512
