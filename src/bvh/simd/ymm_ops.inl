// The lane operations of one ymm register of 8 floats that AVX2 and AVX-512 share, for the lane
// types of box_lanes.inl and packet_lanes.inl; each ISA header adds its own comparison (movemask or
// a mask compare) and includes this inside its namespace (rayvec::avx2 or rayvec::avx512), after
// <immintrin.h>.
struct YmmOps {
  using T = __m256;
  static constexpr int W = 8;
  static RAYVEC_INLINE T set1(float x) { return _mm256_set1_ps(x); }
  static RAYVEC_INLINE T load(const float* p) { return _mm256_load_ps(p); }
  static RAYVEC_INLINE T loadu(const float* p) { return _mm256_loadu_ps(p); }
  static RAYVEC_INLINE void storeu(float* p, T a) { _mm256_storeu_ps(p, a); }
  static RAYVEC_INLINE T sub(T a, T b) { return _mm256_sub_ps(a, b); }
  static RAYVEC_INLINE T mul(T a, T b) { return _mm256_mul_ps(a, b); }
  static RAYVEC_INLINE T max(T a, T b) { return _mm256_max_ps(a, b); }
  static RAYVEC_INLINE T min(T a, T b) { return _mm256_min_ps(a, b); }
  static RAYVEC_INLINE T fmadd(T a, T b, T c) { return _mm256_fmadd_ps(a, b, c); }
  static RAYVEC_INLINE T fnmadd(T a, T b, T c) { return _mm256_fnmadd_ps(a, b, c); }
  static RAYVEC_INLINE T fmsub(T a, T b, T c) { return _mm256_fmsub_ps(a, b, c); }
  static RAYVEC_INLINE T abs(T a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }
};
