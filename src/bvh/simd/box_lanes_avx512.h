// AVX-512 lane types of the wide-BVH box tests (bvh/simd/box_lanes.inl, packet_lanes.inl): a
// ymm of 8 floats with AVX-512VL mask compares (BoxLanes8, WideNode<8>) and a zmm of 16
// (BoxLanes16, WideNode<16>; the 16-ray packets), one register per bounds row. One of the only
// files that include <immintrin.h>; included only by *_avx512.cpp units, in namespace
// rayvec::avx512.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "platform/attributes.h"

namespace rayvec::avx512 {

#include "bvh/simd/ymm_ops.inl"

struct Ymm : YmmOps {
  static RAYVEC_INLINE unsigned le_bits(T a, T b) {
    return unsigned(_mm256_cmp_ps_mask(a, b, _CMP_LE_OQ));
  }
};

struct Zmm {
  using T = __m512;
  static constexpr int W = 16;
  static RAYVEC_INLINE T set1(float x) { return _mm512_set1_ps(x); }
  static RAYVEC_INLINE T load(const float* p) { return _mm512_load_ps(p); }
  static RAYVEC_INLINE void storeu(float* p, T a) { _mm512_storeu_ps(p, a); }
  static RAYVEC_INLINE T sub(T a, T b) { return _mm512_sub_ps(a, b); }
  static RAYVEC_INLINE T mul(T a, T b) { return _mm512_mul_ps(a, b); }
  static RAYVEC_INLINE T max(T a, T b) { return _mm512_max_ps(a, b); }
  static RAYVEC_INLINE T min(T a, T b) { return _mm512_min_ps(a, b); }
  static RAYVEC_INLINE T fmadd(T a, T b, T c) { return _mm512_fmadd_ps(a, b, c); }
  static RAYVEC_INLINE T fnmadd(T a, T b, T c) { return _mm512_fnmadd_ps(a, b, c); }
  static RAYVEC_INLINE T abs(T a) {
    return _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32(INT32_MAX)));
  }
  static RAYVEC_INLINE unsigned le_bits(T a, T b) { return unsigned(_mm512_cmp_ps_mask(a, b, _CMP_LE_OQ)); }
  // packet lanes (packet_lanes.inl): lane masks are __mmask16
  static RAYVEC_INLINE T loadu(const float* p) { return _mm512_loadu_ps(p); }
  static RAYVEC_INLINE T fmsub(T a, T b, T c) { return _mm512_fmsub_ps(a, b, c); }
  using Signs = __mmask16;
  static RAYVEC_INLINE Signs signs_of(T r) { return _mm512_movepi32_mask(_mm512_castps_si512(r)); }
  static RAYVEC_INLINE Signs signs_from_bits(unsigned lanes) { return __mmask16(lanes); }
  static RAYVEC_INLINE T blend(Signs m, T a, T b) { return _mm512_mask_blend_ps(m, a, b); }
  static RAYVEC_INLINE float max_lanes(T v, unsigned lanes) {
    return _mm512_mask_reduce_max_ps(__mmask16(lanes), v);
  }
  static RAYVEC_INLINE float min_lanes(T v, unsigned lanes) {
    return _mm512_mask_reduce_min_ps(__mmask16(lanes), v);
  }
};

#include "bvh/simd/box_lanes.inl"

using BoxLanes8 = BoxLanesOne<Ymm>;
using BoxLanes16 = BoxLanesOne<Zmm>;

}  // namespace rayvec::avx512
