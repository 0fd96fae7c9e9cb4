// AVX2 lane type of the wide-BVH box test (kernels/simd/box_lanes.inl): one ymm of 8 floats, the
// comparison read with movemask. BoxLanes8 tests a WideNode<8> (one ymm per bounds row),
// BoxLanes16 a WideNode<16> (two). One of the only files that include <immintrin.h>; included only
// by *_avx2.cpp units, in namespace rayvec::avx2.
#pragma once
#include <immintrin.h>

#include <cstdint>

namespace rayvec::avx2 {

#ifndef RAYVEC_INLINE
#define RAYVEC_INLINE inline __attribute__((always_inline))
#endif

#include "kernels/simd/ymm_ops.inl"

struct Ymm : YmmOps {
  static RAYVEC_INLINE unsigned le_bits(T a, T b) {
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_LE_OQ)));
  }
};

#include "kernels/simd/box_lanes.inl"

using BoxLanes8 = BoxLanesOne<Ymm>;
using BoxLanes16 = BoxLanesTwo<Ymm>;

}  // namespace rayvec::avx2
