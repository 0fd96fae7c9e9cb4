// The scalar vocabulary of the ray–triangle math shared by the CUDA kernels and the host: one
// source, compiled by nvcc for the device and by g++ for the host tests that check it against the
// CPU kernels (tests/gpu). RAYVEC_HD marks a function for both sides; it is plain `inline` where no
// CUDA compiler is involved, so these headers build in every configuration.
//
// Rounding is made explicit so that both sides compute the same bits: the device code is compiled
// with --fmad=false (nvcc would otherwise fuse `a * b + c`), baseline x86-64 has no FMA to contract
// into, and the one place a fused multiply-add is wanted goes through madd<true>, an explicit FMA on
// both sides (libm's correctly rounded fmaf on the host). madd<false> rounds twice, as the scalar
// CPU kernels do; madd<true> fuses, as the AVX2 and AVX-512 kernels' fmadd does.
#pragma once
#include <cstdint>
#if !defined(__CUDA_ARCH__)
#include <cstring>
#endif

#if defined(__CUDACC__)
#define RAYVEC_HD __host__ __device__ __forceinline__
#else
#define RAYVEC_HD inline
#endif

namespace rayvec::gpu {

RAYVEC_HD uint32_t float_bits(float x) {
#if defined(__CUDA_ARCH__)
  return __float_as_uint(x);
#else
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
#endif
}
RAYVEC_HD float bits_float(uint32_t b) {
#if defined(__CUDA_ARCH__)
  return __uint_as_float(b);
#else
  float x;
  std::memcpy(&x, &b, sizeof x);
  return x;
#endif
}
RAYVEC_HD uint64_t double_bits(double x) {
#if defined(__CUDA_ARCH__)
  return uint64_t(__double_as_longlong(x));
#else
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
#endif
}
RAYVEC_HD double bits_double(uint64_t b) {
#if defined(__CUDA_ARCH__)
  return __longlong_as_double(static_cast<long long>(b));
#else
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
#endif
}

RAYVEC_HD float fused(float a, float b, float c) {
#if defined(__CUDA_ARCH__)
  return __fmaf_rn(a, b, c);
#else
  return __builtin_fmaf(a, b, c);
#endif
}
RAYVEC_HD double fused(double a, double b, double c) {
#if defined(__CUDA_ARCH__)
  return __fma_rn(a, b, c);
#else
  return __builtin_fma(a, b, c);
#endif
}

// a·b + c, fused or rounded twice (see the header comment); a·b − c as madd(a, b, −c) would be with
// FMA, and as a·b − c without.
template <bool Fused, class S>
RAYVEC_HD S madd(S a, S b, S c) {
  if constexpr (Fused)
    return fused(a, b, c);
  else
    return a * b + c;
}
template <bool Fused, class S>
RAYVEC_HD S msub(S a, S b, S c) {
  if constexpr (Fused)
    return fused(a, b, -c);
  else
    return a * b - c;
}

// |x| by clearing the sign bit (a NaN stays a NaN), and x with its sign flipped when `negate`
// holds the sign bit of another value: the SIMD kernels' abs and xor_bits.
RAYVEC_HD float abs_bits(float x) { return bits_float(float_bits(x) & 0x7fffffffu); }
RAYVEC_HD double abs_bits(double x) { return bits_double(double_bits(x) & 0x7fffffffffffffffull); }
RAYVEC_HD uint32_t sign_of(float x) { return float_bits(x) & 0x80000000u; }
RAYVEC_HD uint64_t sign_of(double x) { return double_bits(x) & 0x8000000000000000ull; }
RAYVEC_HD float flip(float x, uint32_t sign) { return bits_float(float_bits(x) ^ sign); }
RAYVEC_HD double flip(double x, uint64_t sign) { return bits_double(double_bits(x) ^ sign); }

// The smallest value greater than x (x itself for +inf and NaN), so `t < next_up(x)` means t <= x.
RAYVEC_HD float next_up(float x) {
  if (!(x == x) || x == bits_float(0x7f800000u)) return x;
  if (x == 0.0f) return bits_float(1u);
  const uint32_t b = float_bits(x);
  return bits_float(x > 0.0f ? b + 1 : b - 1);
}
RAYVEC_HD double next_up(double x) {
  if (!(x == x) || x == bits_double(0x7ff0000000000000ull)) return x;
  if (x == 0.0) return bits_double(1u);
  const uint64_t b = double_bits(x);
  return bits_double(x > 0.0 ? b + 1 : b - 1);
}

// +inf of S.
template <class S>
RAYVEC_HD S infinity() {
  if constexpr (sizeof(S) == 4)
    return bits_float(0x7f800000u);
  else
    return bits_double(0x7ff0000000000000ull);
}

// The x86 rule of the SIMD kernels' vmax: where either is NaN the result is b.
template <class S>
RAYVEC_HD S max_x86(S a, S b) {
  return a > b ? a : b;
}

}  // namespace rayvec::gpu
