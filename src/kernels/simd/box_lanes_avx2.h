// AVX2 ray–box test for the wide BVH: one ray against the 8 child boxes of a WideNode<8> (one
// ymm a bounds row) or the 16 of a WideNode<16> (two), one child per lane. One of the only files that include <immintrin.h>;
// included only by *_avx2.cpp units, inside namespace rayvec::avx2.
// The arithmetic and its robustness argument are documented in bvh/bvh_traversal.inl.
#pragma once
#include <immintrin.h>

#include <cstdint>

namespace rayvec::avx2 {

#ifndef RAYVEC_INLINE
#define RAYVEC_INLINE inline __attribute__((always_inline))
#endif

struct BoxLanes8Ray {
  __m256 ox, oy, oz, rx, ry, rz;
  int nx, ny, nz, fx, fy, fz;  // bounds rows of the near and far planes per axis (0..2 lo, 3..5 hi)
};

// For rays with tmin >= 0: the reciprocals of the near and far planes, already scaled by (1 ∓ eps).
struct BoxLanes8ForwardRay {
  __m256 ox, oy, oz, nrx, nry, nrz, frx, fry, frz;
  int nx, ny, nz, fx, fy, fz;
};

// Eight children whose bound rows are `Stride` floats apart (8 for a WideNode<8>; 16 for either
// half of a WideNode<16>): the slab test of both node widths, written once.
template <int Stride>
struct BoxLanes8Rows {
  // As hits() for a ray with tmin >= 0, the widening done by the scaled reciprocals (see
  // bvh_traversal.inl): three fewer dependent operations a node.
  static RAYVEC_INLINE unsigned hits_forward(const float* b, const BoxLanes8ForwardRay& r, float tmin,
                                             float tmax, float* dist) {
    const __m256 tnx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.nx * Stride), r.ox), r.nrx);
    const __m256 tny = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.ny * Stride), r.oy), r.nry);
    const __m256 tnz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.nz * Stride), r.oz), r.nrz);
    const __m256 tfx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.fx * Stride), r.ox), r.frx);
    const __m256 tfy = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.fy * Stride), r.oy), r.fry);
    const __m256 tfz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.fz * Stride), r.oz), r.frz);
    // the NaN slab (0·inf) is the first operand of each max/min, so it is skipped
    const __m256 lo = _mm256_max_ps(tnz, _mm256_max_ps(tny, _mm256_max_ps(tnx, _mm256_set1_ps(tmin))));
    const __m256 hi = _mm256_min_ps(tfz, _mm256_min_ps(tfy, _mm256_min_ps(tfx, _mm256_set1_ps(tmax))));
    _mm256_storeu_ps(dist, lo);
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ)));
  }

  // Bit k set when child k's box overlaps [tmin, tmax]; dist[k] = its entry distance.
  static RAYVEC_INLINE unsigned hits(const float* b, const BoxLanes8Ray& r, float tmin, float tmax,
                                     float eps, float* dist) {
    const __m256 tnx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.nx * Stride), r.ox), r.rx);
    const __m256 tny = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.ny * Stride), r.oy), r.ry);
    const __m256 tnz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.nz * Stride), r.oz), r.rz);
    const __m256 tfx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.fx * Stride), r.ox), r.rx);
    const __m256 tfy = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.fy * Stride), r.oy), r.ry);
    const __m256 tfz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.fz * Stride), r.oz), r.rz);
    // max/min return the second operand when the first is NaN (0·inf: origin on a plane of an
    // axis the ray is parallel to), so such a slab is skipped
    __m256 tn = _mm256_max_ps(tnx, _mm256_set1_ps(-__builtin_inff()));
    tn = _mm256_max_ps(tny, tn);
    tn = _mm256_max_ps(tnz, tn);
    __m256 tf = _mm256_min_ps(tfx, _mm256_set1_ps(__builtin_inff()));
    tf = _mm256_min_ps(tfy, tf);
    tf = _mm256_min_ps(tfz, tf);
    // widen by |t|·eps; an infinite end becomes NaN, which misses below (the box is unreachable)
    const __m256 e = _mm256_set1_ps(eps);
    tn = _mm256_fnmadd_ps(abs_ps(tn), e, tn);
    tf = _mm256_fmadd_ps(abs_ps(tf), e, tf);
    const __m256 lo = _mm256_max_ps(_mm256_set1_ps(tmin), tn);  // a NaN second operand stays NaN
    const __m256 hi = _mm256_min_ps(_mm256_set1_ps(tmax), tf);
    _mm256_storeu_ps(dist, lo);
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ)));
  }
  static RAYVEC_INLINE __m256 abs_ps(__m256 a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }
};

// The ray constants both node widths share.
struct BoxLanes8Prepare {
  using RayData = BoxLanes8Ray;
  using ForwardRay = BoxLanes8ForwardRay;

  static RAYVEC_INLINE ForwardRay prepare_forward(const float o[3], const float rdir[3], const int near[3],
                                                  float eps) {
    const float dn = 1.0f - eps, up = 1.0f + eps;
    return {_mm256_set1_ps(o[0]), _mm256_set1_ps(o[1]), _mm256_set1_ps(o[2]),
            _mm256_set1_ps(rdir[0] * dn), _mm256_set1_ps(rdir[1] * dn), _mm256_set1_ps(rdir[2] * dn),
            _mm256_set1_ps(rdir[0] * up), _mm256_set1_ps(rdir[1] * up), _mm256_set1_ps(rdir[2] * up),
            near[0], near[1], near[2], near[0] < 3 ? near[0] + 3 : near[0] - 3,
            near[1] < 3 ? near[1] + 3 : near[1] - 3, near[2] < 3 ? near[2] + 3 : near[2] - 3};
  }
  static RAYVEC_INLINE RayData prepare(const float o[3], const float rdir[3], const int near[3]) {
    return {_mm256_set1_ps(o[0]), _mm256_set1_ps(o[1]), _mm256_set1_ps(o[2]),
            _mm256_set1_ps(rdir[0]), _mm256_set1_ps(rdir[1]), _mm256_set1_ps(rdir[2]),
            near[0], near[1], near[2], near[0] < 3 ? near[0] + 3 : near[0] - 3,
            near[1] < 3 ? near[1] + 3 : near[1] - 3, near[2] < 3 ? near[2] + 3 : near[2] - 3};
  }
};

// A WideNode<8>: one ymm per bounds row.
struct BoxLanes8 : BoxLanes8Prepare {
  static constexpr int N = 8;
  static RAYVEC_INLINE unsigned hits_forward(const float (*b)[8], const ForwardRay& r, float tmin,
                                             float tmax, float* dist) {
    return BoxLanes8Rows<8>::hits_forward(b[0], r, tmin, tmax, dist);
  }
  static RAYVEC_INLINE unsigned hits(const float (*b)[8], const RayData& r, float tmin, float tmax,
                                     float eps, float* dist) {
    return BoxLanes8Rows<8>::hits(b[0], r, tmin, tmax, eps, dist);
  }
};

// A WideNode<16>: two ymm halves per bounds row (children 0–7, then 8–15).
struct BoxLanes16 : BoxLanes8Prepare {
  static constexpr int N = 16;
  static RAYVEC_INLINE unsigned hits_forward(const float (*b)[16], const ForwardRay& r, float tmin,
                                             float tmax, float* dist) {
    return BoxLanes8Rows<16>::hits_forward(b[0], r, tmin, tmax, dist) |
           BoxLanes8Rows<16>::hits_forward(b[0] + 8, r, tmin, tmax, dist + 8) << 8;
  }
  static RAYVEC_INLINE unsigned hits(const float (*b)[16], const RayData& r, float tmin, float tmax,
                                     float eps, float* dist) {
    return BoxLanes8Rows<16>::hits(b[0], r, tmin, tmax, eps, dist) |
           BoxLanes8Rows<16>::hits(b[0] + 8, r, tmin, tmax, eps, dist + 8) << 8;
  }
};

}  // namespace rayvec::avx2
