// AVX2 packet lanes for bvh/packet_traversal.inl: 16 rays in two ymm registers (pfloat =
// VPair<vfloat>, simd/vfloat_pair.inl), so that a 4×4 tile is one packet as on AVX-512. The box
// tests are packet_lanes.inl's over pfloat (PacketLanes16: any tmin; its Forward: tmin >= 0, one
// FMA a slab); this file adds the packet's setup (the AoS → SoA transpose of its rays) and a lane
// reduction. One of the
// only files that include <immintrin.h>; included only by *_avx2.cpp units after box_lanes_avx2.h, in
// namespace rayvec::avx2.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "bvh/simd/box_lanes_avx2.h"

namespace rayvec::avx2 {

#include "simd/vfloat_pair.inl"
#include "bvh/simd/packet_lanes.inl"

// The lane type of a packet: two ymm of 8 rays each.
using pfloat = VPair<vfloat>;

// Transposes 8 rays of 8 floats each (the Ray layout: o, d, tmin, tmax; ray k at rays + 8k) into
// rows + f·stride + k (32-byte aligned rows), reading only the rays of `lanes` (bit k: ray k; the
// others' rows are 0). Returns the lanes of `lanes` whose ray is traceable: finite origin and
// direction, tmin and tmax not NaN. The classic 8×8 transpose: unpacklo/hi, shufps, vperm2f128,
// each stage trading one bit of the register index (ray) for one bit of the lane index (field).
RAYVEC_INLINE unsigned transpose_rays8(const float* rays, unsigned lanes, float* rows, int stride) {
  __m256 r[8], s[8];
  for (int j = 0; j < 8; ++j) r[j] = (lanes >> j) & 1u ? _mm256_loadu_ps(rays + 8 * j) : _mm256_setzero_ps();
  for (int j = 0; j < 8; j += 2) {  // slot bit 0 becomes field bit 1
    s[j] = _mm256_unpacklo_ps(r[j], r[j + 1]);
    s[j + 1] = _mm256_unpackhi_ps(r[j], r[j + 1]);
  }
  for (int j : {0, 1, 4, 5}) {  // slot bit 1 becomes field bit 0
    r[j] = _mm256_shuffle_ps(s[j], s[j + 2], 0x44);
    r[j + 2] = _mm256_shuffle_ps(s[j], s[j + 2], 0xee);
  }
  for (int j = 0; j < 4; ++j) {  // slot bit 2 becomes field bit 2
    s[j] = _mm256_permute2f128_ps(r[j], r[j + 4], 0x20);
    s[j + 4] = _mm256_permute2f128_ps(r[j], r[j + 4], 0x31);
  }
  // slot (field bit 2, field bit 0, field bit 1)
  __m256 field[8];
  for (int f = 0; f < 8; ++f) {
    field[f] = s[(f & 4) | ((f & 1) << 1) | ((f & 2) >> 1)];
    _mm256_store_ps(rows + f * stride, field[f]);
  }
  const __m256 inf = _mm256_set1_ps(__builtin_inff()), sign = _mm256_set1_ps(-0.0f);
  __m256 bad = _mm256_cmp_ps(field[6], field[6], _CMP_UNORD_Q);
  bad = _mm256_or_ps(bad, _mm256_cmp_ps(field[7], field[7], _CMP_UNORD_Q));
  for (int f = 0; f < 6; ++f)  // not |x| < inf: NaN or infinite
    bad = _mm256_or_ps(bad, _mm256_cmp_ps(_mm256_andnot_ps(sign, field[f]), inf, _CMP_NLT_UQ));
  return lanes & ~unsigned(_mm256_movemask_ps(bad));
}

struct PacketLanes16 : PacketLanesBase<pfloat, PacketLanes16> {
  template <bool Uniform>
  using Forward = PacketForward<pfloat, Uniform>;

  // Transposes 16 rays into rows[f][k] (f: o, d, tmin, tmax; k: the ray), reading only the rays of
  // `lanes` (the others' rows are 0); returns the traceable lanes (transpose_rays8, per half).
  static RAYVEC_INLINE unsigned load_rays(const float* rays, unsigned lanes, float (*rows)[16]) {
    const unsigned lo = transpose_rays8(rays, lanes & 0xffu, rows[0], 16);
    return lo | transpose_rays8(rays + 64, lanes >> 8, rows[0] + 8, 16) << 8;
  }
  // The smallest of tn over `lanes` (nonzero).
  static RAYVEC_INLINE float min_lanes(const float* tn, unsigned lanes) {
    return hmin_lanes(pfloat::load(tn), lanes);
  }
};

}  // namespace rayvec::avx2
