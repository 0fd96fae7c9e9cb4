// AVX-512 vector types for the kernels: 16 floats or 8 doubles per register, __mmask masks.
// One of the only files that include <immintrin.h>; included only by *_avx512.cpp units, inside
// nothing but its own namespace rayvec::avx512 so no inline function leaks to baseline code.
#pragma once
#include <immintrin.h>

#include <cstdint>
#include <cstring>

#include "platform/attributes.h"

namespace rayvec::avx512 {

struct vmaskf {
  __mmask16 m;
};
struct vmaskd {
  __mmask8 m;
};

struct vfloat {
  static constexpr int W = 16;
  using Mask = vmaskf;
  using Scalar = float;
  __m512 v;
  static RAYVEC_INLINE vfloat load(const float* p) { return {_mm512_loadu_ps(p)}; }
  static RAYVEC_INLINE vfloat load_aligned(const float* p) { return {_mm512_load_ps(p)}; }  // 64 bytes
  static RAYVEC_INLINE vfloat broadcast(float x) { return {_mm512_set1_ps(x)}; }
  // Lane k holds the integer base + k as raw bits (blended bitwise, never used arithmetically).
  static RAYVEC_INLINE vfloat index_bits(uint32_t base) {
    const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    return {_mm512_castsi512_ps(_mm512_add_epi32(_mm512_set1_epi32(int(base)), iota))};
  }
  RAYVEC_INLINE void store(float* out) const { _mm512_storeu_ps(out, v); }
  RAYVEC_INLINE void store_index(int64_t* out) const {
    int32_t tmp[W];
    _mm512_storeu_si512(tmp, _mm512_castps_si512(v));
    for (int k = 0; k < W; ++k) out[k] = tmp[k];
  }
};

struct vdouble {
  static constexpr int W = 8;
  using Mask = vmaskd;
  using Scalar = double;
  __m512d v;
  // Loads W floats and widens them exactly to double.
  static RAYVEC_INLINE vdouble load(const float* p) {
    return {_mm512_maskz_cvtps_pd(__mmask8(0xff), _mm256_loadu_ps(p))};
  }
  static RAYVEC_INLINE vdouble broadcast(double x) { return {_mm512_set1_pd(x)}; }
  static RAYVEC_INLINE vdouble index_bits(uint32_t base) {
    const __m512i iota = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
    return {_mm512_castsi512_pd(_mm512_add_epi64(_mm512_set1_epi64(int64_t(base)), iota))};
  }
  RAYVEC_INLINE void store(double* out) const { _mm512_storeu_pd(out, v); }
  RAYVEC_INLINE void store_index(int64_t* out) const { _mm512_storeu_si512(out, _mm512_castpd_si512(v)); }
};

// arithmetic
RAYVEC_INLINE vfloat operator+(vfloat a, vfloat b) { return {_mm512_add_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat operator-(vfloat a, vfloat b) { return {_mm512_sub_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat operator*(vfloat a, vfloat b) { return {_mm512_mul_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat operator/(vfloat a, vfloat b) { return {_mm512_div_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat fmadd(vfloat a, vfloat b, vfloat c) { return {_mm512_fmadd_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat fmsub(vfloat a, vfloat b, vfloat c) { return {_mm512_fmsub_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat fnmadd(vfloat a, vfloat b, vfloat c) { return {_mm512_fnmadd_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat abs(vfloat a) {
  return {_mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a.v), _mm512_set1_epi32(INT32_MAX)))};
}
RAYVEC_INLINE vfloat sign_bit(vfloat a) {
  return {_mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a.v), _mm512_set1_epi32(INT32_MIN)))};
}
RAYVEC_INLINE vfloat xor_bits(vfloat a, vfloat b) {
  return {_mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a.v), _mm512_castps_si512(b.v)))};
}
RAYVEC_INLINE vfloat and_bits(vfloat a, vfloat b) {
  return {_mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a.v), _mm512_castps_si512(b.v)))};
}
// a with its sign flipped in the lanes where s is negative: a ^ (s & sign bit) in one instruction
// (0x78 = A ^ (B & C)), where sign_bit and xor_bits would take two.
RAYVEC_INLINE vfloat xor_sign(vfloat a, vfloat s) {
  return {_mm512_castsi512_ps(_mm512_ternarylogic_epi32(_mm512_castps_si512(a.v), _mm512_castps_si512(s.v),
                                                        _mm512_set1_epi32(INT32_MIN), 0x78))};
}
// ±1 with the sign of s in each lane: (s & sign bit) | 1.0 in one instruction (0xF8 = A | (B & C)).
// Multiplying by it flips a value where xor_sign(·, s) would, and fits into an FMA.
RAYVEC_INLINE vfloat sign_one(vfloat s) {
  return {_mm512_castsi512_ps(_mm512_ternarylogic_epi32(_mm512_castps_si512(_mm512_set1_ps(1.0f)),
                                                        _mm512_castps_si512(s.v),
                                                        _mm512_set1_epi32(INT32_MIN), 0xF8))};
}
RAYVEC_INLINE vdouble operator+(vdouble a, vdouble b) { return {_mm512_add_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble operator-(vdouble a, vdouble b) { return {_mm512_sub_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble operator*(vdouble a, vdouble b) { return {_mm512_mul_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble operator/(vdouble a, vdouble b) { return {_mm512_div_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble fmadd(vdouble a, vdouble b, vdouble c) { return {_mm512_fmadd_pd(a.v, b.v, c.v)}; }
RAYVEC_INLINE vdouble fmsub(vdouble a, vdouble b, vdouble c) { return {_mm512_fmsub_pd(a.v, b.v, c.v)}; }
RAYVEC_INLINE vdouble abs(vdouble a) {
  return {_mm512_castsi512_pd(_mm512_and_si512(_mm512_castpd_si512(a.v), _mm512_set1_epi64(INT64_MAX)))};
}
RAYVEC_INLINE vdouble sign_bit(vdouble a) {
  return {_mm512_castsi512_pd(_mm512_and_si512(_mm512_castpd_si512(a.v), _mm512_set1_epi64(INT64_MIN)))};
}
RAYVEC_INLINE vdouble xor_bits(vdouble a, vdouble b) {
  return {_mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(a.v), _mm512_castpd_si512(b.v)))};
}

// ordered, quiet comparisons: false whenever either side is NaN
RAYVEC_INLINE vmaskf operator>=(vfloat a, vfloat b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ)}; }
RAYVEC_INLINE vmaskf operator<=(vfloat a, vfloat b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)}; }
RAYVEC_INLINE vmaskf operator>(vfloat a, vfloat b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ)}; }
RAYVEC_INLINE vmaskf operator<(vfloat a, vfloat b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)}; }
RAYVEC_INLINE vmaskd operator>=(vdouble a, vdouble b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)}; }
RAYVEC_INLINE vmaskd operator<=(vdouble a, vdouble b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)}; }
RAYVEC_INLINE vmaskd operator>(vdouble a, vdouble b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)}; }
RAYVEC_INLINE vmaskd operator<(vdouble a, vdouble b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }

// masks
RAYVEC_INLINE vmaskf operator&(vmaskf a, vmaskf b) { return {__mmask16(a.m & b.m)}; }
RAYVEC_INLINE vmaskd operator&(vmaskd a, vmaskd b) { return {__mmask8(a.m & b.m)}; }
RAYVEC_INLINE bool any(vmaskf a) { return a.m != 0; }
RAYVEC_INLINE bool any(vmaskd a) { return a.m != 0; }
RAYVEC_INLINE unsigned bits(vmaskf a) { return a.m; }
RAYVEC_INLINE unsigned bits(vmaskd a) { return a.m; }
// The first n lanes (n may exceed W).
RAYVEC_INLINE vmaskf first_lanes(vfloat, uint32_t n) {
  return {n >= 16 ? __mmask16(0xffff) : __mmask16((1u << n) - 1)};
}
RAYVEC_INLINE vmaskd first_lanes(vdouble, uint32_t n) {
  return {n >= 8 ? __mmask8(0xff) : __mmask8((1u << n) - 1)};
}
// Lanes lo <= k < hi (lo <= hi; both may exceed W).
RAYVEC_INLINE vmaskf lanes_between(vfloat v, uint32_t lo, uint32_t hi) {
  return {__mmask16(first_lanes(v, hi).m & ~first_lanes(v, lo).m)};
}
RAYVEC_INLINE vmaskd lanes_between(vdouble v, uint32_t lo, uint32_t hi) {
  return {__mmask8(first_lanes(v, hi).m & ~first_lanes(v, lo).m)};
}
// Lanes of b where m is set, of a elsewhere.
RAYVEC_INLINE vfloat select(vmaskf m, vfloat a, vfloat b) { return {_mm512_mask_blend_ps(m.m, a.v, b.v)}; }
RAYVEC_INLINE vdouble select(vmaskd m, vdouble a, vdouble b) { return {_mm512_mask_blend_pd(m.m, a.v, b.v)}; }

// The smallest lane (NaN lanes are ignored unless all are NaN).
RAYVEC_INLINE float hmin(vfloat a) {
  __m256 m = _mm256_min_ps(_mm512_castps512_ps256(a.v), _mm512_extractf32x8_ps(a.v, 1));
  __m128 q = _mm_min_ps(_mm256_castps256_ps128(m), _mm256_extractf128_ps(m, 1));
  q = _mm_min_ps(q, _mm_movehl_ps(q, q));
  q = _mm_min_ss(q, _mm_movehdup_ps(q));
  return _mm_cvtss_f32(q);
}

// The lanes whose bit is set in b (bit k: lane k); the inverse of bits().
RAYVEC_INLINE vmaskf mask_from_bits(vfloat, unsigned b) { return {__mmask16(b)}; }

// Lane-wise min and max; where either lane is NaN the result is b's lane (the x86 rule, relied on
// to skip NaN slabs and infinite widenings in box tests).
// (maskz with every lane: the plain intrinsics merge into _mm512_undefined_ps(), which g++ 12
// reports as an uninitialized use when the operands are constants.)
RAYVEC_INLINE vfloat vmin(vfloat a, vfloat b) { return {_mm512_maskz_min_ps(__mmask16(0xffff), a.v, b.v)}; }
RAYVEC_INLINE vfloat vmax(vfloat a, vfloat b) { return {_mm512_maskz_max_ps(__mmask16(0xffff), a.v, b.v)}; }

// The lanes whose sign bit is set (negative, −0, or a NaN with its sign set).
RAYVEC_INLINE vmaskf sign_mask(vfloat a) { return {_mm512_movepi32_mask(_mm512_castps_si512(a.v))}; }

// next_up (kernels/moller_trumbore.inl) lane by lane: the smallest value greater than x, x itself
// for +inf and NaN; ±0 gives the smallest subnormal, −inf the most negative finite value.
RAYVEC_INLINE vfloat next_up(vfloat x) {
  const __m512i b = _mm512_castps_si512(x.v), one = _mm512_set1_epi32(1);
  const __m512 zero = _mm512_setzero_ps();
  // a positive x moves away from zero, a negative one toward it: one unit of its bits either way
  __m512i r =
      _mm512_mask_add_epi32(_mm512_sub_epi32(b, one), _mm512_cmp_ps_mask(x.v, zero, _CMP_GT_OQ), b, one);
  r = _mm512_mask_mov_epi32(r, _mm512_cmp_ps_mask(x.v, zero, _CMP_EQ_OQ), one);
  const __mmask16 keep = __mmask16(_mm512_cmp_ps_mask(x.v, x.v, _CMP_UNORD_Q) |
                                   _mm512_cmp_ps_mask(x.v, _mm512_set1_ps(__builtin_inff()), _CMP_EQ_OQ));
  return {_mm512_mask_mov_ps(_mm512_castsi512_ps(r), keep, x.v)};
}

// The smallest and the largest of v over `lanes` (bit k: lane k; nonzero).
RAYVEC_INLINE float hmin_lanes(vfloat v, unsigned lanes) {
  return _mm512_mask_reduce_min_ps(__mmask16(lanes), v.v);
}
RAYVEC_INLINE float hmax_lanes(vfloat v, unsigned lanes) {
  return _mm512_mask_reduce_max_ps(__mmask16(lanes), v.v);
}

// Bitwise or of three vectors, and the lanes whose sign bit is clear (+0, positive, +inf, or a NaN
// with a clear sign): the float `mt` pre-test ORs its values and tests the sign once
// (mt_float.inl, mt_sign_pretest).
RAYVEC_INLINE vfloat or3(vfloat a, vfloat b, vfloat c) {
  return {_mm512_castsi512_ps(_mm512_ternarylogic_epi32(_mm512_castps_si512(a.v), _mm512_castps_si512(b.v),
                                                        _mm512_castps_si512(c.v), 0xFE))};
}
RAYVEC_INLINE vmaskf sign_clear(vfloat a) {
  return {_mm512_testn_epi32_mask(_mm512_castps_si512(a.v), _mm512_set1_epi32(INT32_MIN))};
}
// any(active & sign_clear(a)), the mask left unformed
RAYVEC_INLINE bool any_sign_clear(vmaskf active, vfloat a) {
  return _mm512_mask_testn_epi32_mask(active.m, _mm512_castps_si512(a.v), _mm512_set1_epi32(INT32_MIN)) != 0;
}

// vfloat8: 8 floats in a ymm register with AVX-512VL mask compares — the lane type of 8-wide BVH
// nodes (bvh/simd/box_lanes.inl), where a zmm would test 8 children that do not exist. Only what the
// box test needs.
struct vmask8 {
  __mmask8 m;
};

struct vfloat8 {
  static constexpr int W = 8;
  using Mask = vmask8;
  using Scalar = float;
  __m256 v;
  static RAYVEC_INLINE vfloat8 load(const float* p) { return {_mm256_loadu_ps(p)}; }
  static RAYVEC_INLINE vfloat8 load_aligned(const float* p) { return {_mm256_load_ps(p)}; }  // 32 bytes
  static RAYVEC_INLINE vfloat8 broadcast(float x) { return {_mm256_set1_ps(x)}; }
  RAYVEC_INLINE void store(float* out) const { _mm256_storeu_ps(out, v); }
};

RAYVEC_INLINE vfloat8 operator-(vfloat8 a, vfloat8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat8 operator*(vfloat8 a, vfloat8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat8 fmadd(vfloat8 a, vfloat8 b, vfloat8 c) { return {_mm256_fmadd_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat8 fmsub(vfloat8 a, vfloat8 b, vfloat8 c) { return {_mm256_fmsub_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat8 fnmadd(vfloat8 a, vfloat8 b, vfloat8 c) { return {_mm256_fnmadd_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat8 abs(vfloat8 a) { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)}; }
// NaN rule as vfloat's: where either lane is NaN the result is b's lane.
RAYVEC_INLINE vfloat8 vmin(vfloat8 a, vfloat8 b) { return {_mm256_min_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat8 vmax(vfloat8 a, vfloat8 b) { return {_mm256_max_ps(a.v, b.v)}; }
RAYVEC_INLINE vmask8 operator<=(vfloat8 a, vfloat8 b) { return {_mm256_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)}; }
RAYVEC_INLINE unsigned bits(vmask8 a) { return a.m; }

}  // namespace rayvec::avx512
