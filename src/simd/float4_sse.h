// Float4: four float lanes in one SSE register, for baseline code (SSE2 is part of x86-64, so no
// ISA unit or run-time dispatch is needed). The BVH builder bins a triangle's box (three coordinates
// and a spare lane) with it. Include only from units compiled with the baseline flags: an out-of-line
// copy compiled with AVX flags in an ISA unit could be shared with baseline callers. Without SSE2
// (another architecture) the same operations run lane by lane.
#pragma once
#include <cstdint>

#include "platform/attributes.h"

#if defined(__SSE2__)
#include <immintrin.h>
#else
#include <cmath>
#endif

namespace rayvec::sse {

#if defined(__SSE2__)

struct Float4 {
  __m128 v;
  static RAYVEC_INLINE Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }
  static RAYVEC_INLINE Float4 set(float x, float y, float z, float w) { return {_mm_setr_ps(x, y, z, w)}; }
  static RAYVEC_INLINE Float4 broadcast(float x) { return {_mm_set1_ps(x)}; }
  RAYVEC_INLINE void store(float* p) const { _mm_storeu_ps(p, v); }
  // Lanes 0-2 kept, lane 3 set to +0 (a spare lane that may hold other bits, e.g. an id).
  RAYVEC_INLINE Float4 xyz() const {
    return {_mm_and_ps(v, _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)))};
  }
  // This value with lane `lane` (0-3) replaced by x, in registers: a lane written to memory and the
  // vector loaded back stalls on the failed store forwarding.
  RAYVEC_INLINE Float4 with_lane(int lane, float x) const {
    alignas(16) static constexpr int32_t kLaneMask[4][4] = {
        {-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}, {0, 0, 0, -1}};
    const __m128 m = _mm_load_ps(reinterpret_cast<const float*>(kLaneMask[lane]));
    return {_mm_or_ps(_mm_andnot_ps(m, v), _mm_and_ps(m, _mm_set1_ps(x)))};
  }
  // Truncation toward zero of each lane (lanes out of the int32 range give INT32_MIN).
  RAYVEC_INLINE void store_truncated(int32_t* p) const {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm_cvttps_epi32(v));
  }
};

RAYVEC_INLINE Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
RAYVEC_INLINE Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
RAYVEC_INLINE Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
// Correctly rounded, as the scalar / and std::sqrt are: a lane gives the scalar operation's bits.
RAYVEC_INLINE Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
RAYVEC_INLINE Float4 vsqrt(Float4 a) { return {_mm_sqrt_ps(a.v)}; }
// Min and max by the x86 rule: a < b ? a : b (and a > b ? a : b), so where either is NaN the result
// is b — pass the accumulator as b to keep it when the new value is NaN.
RAYVEC_INLINE Float4 vmin(Float4 a, Float4 b) { return {_mm_min_ps(a.v, b.v)}; }
RAYVEC_INLINE Float4 vmax(Float4 a, Float4 b) { return {_mm_max_ps(a.v, b.v)}; }
// Half the surface area of the box lo..hi in lanes 0-2: x·y + y·z + z·x of its extent, in that
// order (BBox::half_area's arithmetic, so the same bits), 0 when it is empty along any axis.
RAYVEC_INLINE float half_area(Float4 lo, Float4 hi) {
  if ((_mm_movemask_ps(_mm_cmple_ps(lo.v, hi.v)) & 7) != 7) return 0.0f;
  const __m128 e = _mm_sub_ps(hi.v, lo.v);
  const __m128 p = _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1)));  // x·y, y·z, z·x
  const __m128 xy_yz = _mm_add_ss(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(3, 3, 3, 1)));
  return _mm_cvtss_f32(_mm_add_ss(xy_yz, _mm_movehl_ps(p, p)));
}

#else

struct Float4 {
  float v[4];
  static RAYVEC_INLINE Float4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
  static RAYVEC_INLINE Float4 set(float x, float y, float z, float w) { return {{x, y, z, w}}; }
  static RAYVEC_INLINE Float4 broadcast(float x) { return {{x, x, x, x}}; }
  RAYVEC_INLINE void store(float* p) const {
    for (int i = 0; i < 4; ++i) p[i] = v[i];
  }
  RAYVEC_INLINE Float4 xyz() const { return {{v[0], v[1], v[2], 0.0f}}; }
  RAYVEC_INLINE Float4 with_lane(int lane, float x) const {
    Float4 r = *this;
    r.v[lane] = x;
    return r;
  }
  RAYVEC_INLINE void store_truncated(int32_t* p) const {
    for (int i = 0; i < 4; ++i)
      p[i] = v[i] > -2147483648.0f && v[i] < 2147483648.0f ? int32_t(v[i]) : INT32_MIN;
  }
};

template <class Op>
RAYVEC_INLINE Float4 lanewise(Float4 a, Float4 b, Op op) {
  Float4 r;
  for (int i = 0; i < 4; ++i) r.v[i] = op(a.v[i], b.v[i]);
  return r;
}
RAYVEC_INLINE Float4 operator+(Float4 a, Float4 b) {
  return lanewise(a, b, [](float x, float y) { return x + y; });
}
RAYVEC_INLINE Float4 operator-(Float4 a, Float4 b) {
  return lanewise(a, b, [](float x, float y) { return x - y; });
}
RAYVEC_INLINE Float4 operator*(Float4 a, Float4 b) {
  return lanewise(a, b, [](float x, float y) { return x * y; });
}
RAYVEC_INLINE Float4 operator/(Float4 a, Float4 b) {
  return lanewise(a, b, [](float x, float y) { return x / y; });
}
RAYVEC_INLINE Float4 vsqrt(Float4 a) {
  return lanewise(a, a, [](float x, float) { return std::sqrt(x); });
}
RAYVEC_INLINE Float4 vmin(Float4 a, Float4 b) {
  return lanewise(a, b, [](float x, float y) { return x < y ? x : y; });
}
RAYVEC_INLINE Float4 vmax(Float4 a, Float4 b) {
  return lanewise(a, b, [](float x, float y) { return x > y ? x : y; });
}
RAYVEC_INLINE float half_area(Float4 lo, Float4 hi) {
  if (!(lo.v[0] <= hi.v[0] && lo.v[1] <= hi.v[1] && lo.v[2] <= hi.v[2])) return 0.0f;
  const float x = hi.v[0] - lo.v[0], y = hi.v[1] - lo.v[1], z = hi.v[2] - lo.v[2];
  return x * y + y * z + z * x;
}

#endif

}  // namespace rayvec::sse
