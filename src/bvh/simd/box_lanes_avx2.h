// AVX2 lane type of the wide-BVH box tests (bvh/simd/box_lanes.inl, packet_lanes.inl): one ymm
// of 8 floats, the comparison read with movemask, lane masks as sign bits. BoxLanes8 tests a
// WideNode<8> (one ymm per bounds row), BoxLanes16 a WideNode<16> (two). One of the only files that
// include <immintrin.h>; included only by *_avx2.cpp units, in namespace rayvec::avx2.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "platform/attributes.h"

namespace rayvec::avx2 {

#include "bvh/simd/ymm_ops.inl"

struct Ymm : YmmOps {
  static RAYVEC_INLINE unsigned le_bits(T a, T b) {
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_LE_OQ)));
  }
  // packet lanes (packet_lanes.inl): a lane mask is a vector whose sign bits select (blendv)
  using Signs = __m256;
  static RAYVEC_INLINE Signs signs_of(T r) { return r; }
  static RAYVEC_INLINE Signs signs_from_bits(unsigned lanes) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i m = _mm256_and_si256(_mm256_set1_epi32(int(lanes)), bit);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(m, bit));
  }
  static RAYVEC_INLINE T blend(Signs m, T a, T b) { return _mm256_blendv_ps(a, b, m); }
  // The smallest lane.
  static RAYVEC_INLINE float hmin(T v) {
    __m128 x = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    x = _mm_min_ps(x, _mm_movehl_ps(x, x));
    x = _mm_min_ss(x, _mm_shuffle_ps(x, x, 1));
    return _mm_cvtss_f32(x);
  }
  // The largest of v over `lanes` (nonzero).
  static RAYVEC_INLINE float max_lanes(T v, unsigned lanes) {
    const T neg = _mm256_xor_ps(v, _mm256_set1_ps(-0.0f));
    return -hmin(_mm256_blendv_ps(_mm256_set1_ps(__builtin_inff()), neg, signs_from_bits(lanes)));
  }
  // The smallest of v over `lanes` (nonzero).
  static RAYVEC_INLINE float min_lanes(T v, unsigned lanes) {
    return hmin(_mm256_blendv_ps(_mm256_set1_ps(__builtin_inff()), v, signs_from_bits(lanes)));
  }
};

#include "bvh/simd/box_lanes.inl"

using BoxLanes8 = BoxLanesOne<Ymm>;
using BoxLanes16 = BoxLanesTwo<Ymm>;

}  // namespace rayvec::avx2
