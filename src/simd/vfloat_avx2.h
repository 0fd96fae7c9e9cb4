// AVX2 + FMA vector types for the kernels: 8 floats or 4 doubles per register; masks are full-width
// compare results. One of the only files that include <immintrin.h>; included only by *_avx2.cpp
// units, inside its own namespace rayvec::avx2.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "platform/attributes.h"

namespace rayvec::avx2 {

struct vmaskf {
  __m256 m;
};
struct vmaskd {
  __m256d m;
};

struct vfloat {
  static constexpr int W = 8;
  using Mask = vmaskf;
  using Scalar = float;
  __m256 v;
  static RAYVEC_INLINE vfloat load(const float* p) { return {_mm256_loadu_ps(p)}; }
  static RAYVEC_INLINE vfloat load_aligned(const float* p) { return {_mm256_load_ps(p)}; }  // 32 bytes
  static RAYVEC_INLINE vfloat broadcast(float x) { return {_mm256_set1_ps(x)}; }
  static RAYVEC_INLINE vfloat index_bits(uint32_t base) {
    const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    return {_mm256_castsi256_ps(_mm256_add_epi32(_mm256_set1_epi32(int(base)), iota))};
  }
  RAYVEC_INLINE void store(float* out) const { _mm256_storeu_ps(out, v); }
  RAYVEC_INLINE void store_index(int64_t* out) const {
    int32_t tmp[W];
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(tmp), _mm256_castps_si256(v));
    for (int k = 0; k < W; ++k) out[k] = tmp[k];
  }
};

struct vdouble {
  static constexpr int W = 4;
  using Mask = vmaskd;
  using Scalar = double;
  __m256d v;
  static RAYVEC_INLINE vdouble load(const float* p) { return {_mm256_cvtps_pd(_mm_loadu_ps(p))}; }
  static RAYVEC_INLINE vdouble broadcast(double x) { return {_mm256_set1_pd(x)}; }
  static RAYVEC_INLINE vdouble index_bits(uint32_t base) {
    const __m256i iota = _mm256_setr_epi64x(0, 1, 2, 3);
    return {_mm256_castsi256_pd(_mm256_add_epi64(_mm256_set1_epi64x(int64_t(base)), iota))};
  }
  RAYVEC_INLINE void store(double* out) const { _mm256_storeu_pd(out, v); }
  RAYVEC_INLINE void store_index(int64_t* out) const {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_castpd_si256(v));
  }
};

RAYVEC_INLINE vfloat operator+(vfloat a, vfloat b) { return {_mm256_add_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat operator-(vfloat a, vfloat b) { return {_mm256_sub_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat operator*(vfloat a, vfloat b) { return {_mm256_mul_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat operator/(vfloat a, vfloat b) { return {_mm256_div_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat fmadd(vfloat a, vfloat b, vfloat c) { return {_mm256_fmadd_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat fmsub(vfloat a, vfloat b, vfloat c) { return {_mm256_fmsub_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat fnmadd(vfloat a, vfloat b, vfloat c) { return {_mm256_fnmadd_ps(a.v, b.v, c.v)}; }
RAYVEC_INLINE vfloat abs(vfloat a) { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)}; }
RAYVEC_INLINE vfloat sign_bit(vfloat a) { return {_mm256_and_ps(_mm256_set1_ps(-0.0f), a.v)}; }
RAYVEC_INLINE vfloat xor_bits(vfloat a, vfloat b) { return {_mm256_xor_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat and_bits(vfloat a, vfloat b) { return {_mm256_and_ps(a.v, b.v)}; }
// a with its sign flipped in the lanes where s is negative
RAYVEC_INLINE vfloat xor_sign(vfloat a, vfloat s) { return xor_bits(a, sign_bit(s)); }
// ±1 with the sign of s in each lane (multiplying by it flips where xor_sign(·, s) would)
RAYVEC_INLINE vfloat sign_one(vfloat s) { return {_mm256_or_ps(sign_bit(s).v, _mm256_set1_ps(1.0f))}; }
RAYVEC_INLINE vdouble operator+(vdouble a, vdouble b) { return {_mm256_add_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble operator-(vdouble a, vdouble b) { return {_mm256_sub_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble operator*(vdouble a, vdouble b) { return {_mm256_mul_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble operator/(vdouble a, vdouble b) { return {_mm256_div_pd(a.v, b.v)}; }
RAYVEC_INLINE vdouble fmadd(vdouble a, vdouble b, vdouble c) { return {_mm256_fmadd_pd(a.v, b.v, c.v)}; }
RAYVEC_INLINE vdouble fmsub(vdouble a, vdouble b, vdouble c) { return {_mm256_fmsub_pd(a.v, b.v, c.v)}; }
RAYVEC_INLINE vdouble abs(vdouble a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
RAYVEC_INLINE vdouble sign_bit(vdouble a) { return {_mm256_and_pd(_mm256_set1_pd(-0.0), a.v)}; }
RAYVEC_INLINE vdouble xor_bits(vdouble a, vdouble b) { return {_mm256_xor_pd(a.v, b.v)}; }

// ordered, quiet comparisons: false whenever either side is NaN
RAYVEC_INLINE vmaskf operator>=(vfloat a, vfloat b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
RAYVEC_INLINE vmaskf operator<=(vfloat a, vfloat b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)}; }
RAYVEC_INLINE vmaskf operator>(vfloat a, vfloat b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
RAYVEC_INLINE vmaskf operator<(vfloat a, vfloat b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
RAYVEC_INLINE vmaskd operator>=(vdouble a, vdouble b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)}; }
RAYVEC_INLINE vmaskd operator<=(vdouble a, vdouble b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
RAYVEC_INLINE vmaskd operator>(vdouble a, vdouble b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
RAYVEC_INLINE vmaskd operator<(vdouble a, vdouble b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }

// In the integer domain: g++ sees through its vector-extension form, so a mask of all lanes (a full
// kernel step's first_lanes) folds away and an and with sign_clear becomes one vandnps.
RAYVEC_INLINE vmaskf operator&(vmaskf a, vmaskf b) {
  return {_mm256_castsi256_ps(_mm256_and_si256(_mm256_castps_si256(a.m), _mm256_castps_si256(b.m)))};
}
RAYVEC_INLINE vmaskd operator&(vmaskd a, vmaskd b) { return {_mm256_and_pd(a.m, b.m)}; }
RAYVEC_INLINE bool any(vmaskf a) { return _mm256_movemask_ps(a.m) != 0; }
RAYVEC_INLINE bool any(vmaskd a) { return _mm256_movemask_pd(a.m) != 0; }
RAYVEC_INLINE unsigned bits(vmaskf a) { return unsigned(_mm256_movemask_ps(a.m)); }
RAYVEC_INLINE unsigned bits(vmaskd a) { return unsigned(_mm256_movemask_pd(a.m)); }
RAYVEC_INLINE vmaskf first_lanes(vfloat, uint32_t n) {
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const int limit = n >= 8 ? 8 : int(n);
  return {_mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(limit), iota))};
}
RAYVEC_INLINE vmaskd first_lanes(vdouble, uint32_t n) {
  const __m256i iota = _mm256_setr_epi64x(0, 1, 2, 3);
  const int64_t limit = n >= 4 ? 4 : int64_t(n);
  return {_mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(limit), iota))};
}
// Lanes lo <= k < hi (lo <= hi; both may exceed W).
RAYVEC_INLINE vmaskf lanes_between(vfloat v, uint32_t lo, uint32_t hi) {
  return {_mm256_andnot_ps(first_lanes(v, lo).m, first_lanes(v, hi).m)};
}
RAYVEC_INLINE vmaskd lanes_between(vdouble v, uint32_t lo, uint32_t hi) {
  return {_mm256_andnot_pd(first_lanes(v, lo).m, first_lanes(v, hi).m)};
}
RAYVEC_INLINE vfloat select(vmaskf m, vfloat a, vfloat b) { return {_mm256_blendv_ps(a.v, b.v, m.m)}; }
RAYVEC_INLINE vdouble select(vmaskd m, vdouble a, vdouble b) { return {_mm256_blendv_pd(a.v, b.v, m.m)}; }

// The smallest lane (NaN lanes are ignored unless all are NaN).
RAYVEC_INLINE float hmin(vfloat a) {
  __m128 q = _mm_min_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1));
  q = _mm_min_ps(q, _mm_movehl_ps(q, q));
  q = _mm_min_ss(q, _mm_movehdup_ps(q));
  return _mm_cvtss_f32(q);
}

// The lanes whose bit is set in b (bit k: lane k); the inverse of bits().
RAYVEC_INLINE vmaskf mask_from_bits(vfloat, unsigned b) {
  const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  const __m256i m = _mm256_and_si256(_mm256_set1_epi32(int(b)), bit);
  return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(m, bit))};
}

// Lane-wise min and max; where either lane is NaN the result is b's lane (the x86 rule, relied on
// to skip NaN slabs and infinite widenings in box tests).
RAYVEC_INLINE vfloat vmin(vfloat a, vfloat b) { return {_mm256_min_ps(a.v, b.v)}; }
RAYVEC_INLINE vfloat vmax(vfloat a, vfloat b) { return {_mm256_max_ps(a.v, b.v)}; }

// The lanes whose sign bit is set (negative, −0, or a NaN with its sign set). A mask of sign bits
// only: select and bits read nothing else.
RAYVEC_INLINE vmaskf sign_mask(vfloat a) { return {a.v}; }

// next_up (kernels/moller_trumbore.inl) lane by lane: the smallest value greater than x, x itself
// for +inf and NaN; ±0 gives the smallest subnormal, −inf the most negative finite value.
RAYVEC_INLINE vfloat next_up(vfloat x) {
  const __m256i b = _mm256_castps_si256(x.v), one = _mm256_set1_epi32(1);
  const __m256 zero = _mm256_setzero_ps();
  // a positive x moves away from zero, a negative one toward it: one unit of its bits either way
  __m256 r =
      _mm256_blendv_ps(_mm256_castsi256_ps(_mm256_sub_epi32(b, one)),
                       _mm256_castsi256_ps(_mm256_add_epi32(b, one)), _mm256_cmp_ps(x.v, zero, _CMP_GT_OQ));
  r = _mm256_blendv_ps(r, _mm256_castsi256_ps(one), _mm256_cmp_ps(x.v, zero, _CMP_EQ_OQ));
  const __m256 keep = _mm256_or_ps(_mm256_cmp_ps(x.v, x.v, _CMP_UNORD_Q),
                                   _mm256_cmp_ps(x.v, _mm256_set1_ps(__builtin_inff()), _CMP_EQ_OQ));
  return {_mm256_blendv_ps(r, x.v, keep)};
}

// The smallest and the largest of v over `lanes` (bit k: lane k; nonzero).
RAYVEC_INLINE float hmin_lanes(vfloat v, unsigned lanes) {
  return hmin(select(mask_from_bits(v, lanes), vfloat::broadcast(__builtin_inff()), v));
}
RAYVEC_INLINE float hmax_lanes(vfloat v, unsigned lanes) {
  const vfloat neg = xor_bits(v, vfloat::broadcast(-0.0f));
  return -hmin(select(mask_from_bits(v, lanes), vfloat::broadcast(__builtin_inff()), neg));
}

// Bitwise or of three vectors, and the lanes whose sign bit is clear (+0, positive, +inf, or a NaN
// with a clear sign): the float `mt` pre-test ORs its values and tests the sign once
// (mt_float.inl, mt_sign_pretest).
RAYVEC_INLINE vfloat or3(vfloat a, vfloat b, vfloat c) { return {_mm256_or_ps(_mm256_or_ps(a.v, b.v), c.v)}; }
// A mask of sign bits only, as sign_mask: the complement of a's bits.
RAYVEC_INLINE vmaskf sign_clear(vfloat a) {
  return {_mm256_castsi256_ps(_mm256_xor_si256(_mm256_castps_si256(a.v), _mm256_set1_epi32(-1)))};
}
// any(active & sign_clear(a)), the mask left unformed: the sign bits as integers (a full step's
// active lanes fold to 0xff), where forming the mask first takes a vpxor. vtestps measured slower.
RAYVEC_INLINE bool any_sign_clear(vmaskf active, vfloat a) {
  return (unsigned(_mm256_movemask_ps(active.m)) & ~unsigned(_mm256_movemask_ps(a.v))) != 0;
}

}  // namespace rayvec::avx2
