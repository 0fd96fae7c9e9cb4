// Scalar "vector" types (one lane) so the same kernel body compiles for baseline x86-64.
// Included only by *_scalar.cpp kernel units, inside namespace rayvec::scalar.
#pragma once
#include <bit>
#include <cstdint>

#include "platform/attributes.h"

namespace rayvec::scalar {

struct vmask {
  bool m;
};

template <typename T, typename Bits>
struct vlane {
  static constexpr int W = 1;
  using Mask = vmask;
  using Scalar = T;
  T v;
  static RAYVEC_INLINE vlane load(const float* p) { return {T(*p)}; }
  static RAYVEC_INLINE vlane load_aligned(const float* p) { return {T(*p)}; }
  static RAYVEC_INLINE vlane broadcast(T x) { return {x}; }
  static RAYVEC_INLINE vlane index_bits(uint32_t base) { return {std::bit_cast<T>(Bits(base))}; }
  RAYVEC_INLINE void store(T* out) const { *out = v; }
  RAYVEC_INLINE void store_index(int64_t* out) const { *out = int64_t(std::bit_cast<Bits>(v)); }
};
using vfloat = vlane<float, uint32_t>;
using vdouble = vlane<double, uint64_t>;

template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> operator+(vlane<T, B> a, vlane<T, B> b) {
  return {a.v + b.v};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> operator-(vlane<T, B> a, vlane<T, B> b) {
  return {a.v - b.v};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> operator*(vlane<T, B> a, vlane<T, B> b) {
  return {a.v * b.v};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> operator/(vlane<T, B> a, vlane<T, B> b) {
  return {a.v / b.v};
}
// No FMA in baseline x86-64: a multiply and an add, each rounded.
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> fmadd(vlane<T, B> a, vlane<T, B> b, vlane<T, B> c) {
  return {a.v * b.v + c.v};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> fmsub(vlane<T, B> a, vlane<T, B> b, vlane<T, B> c) {
  return {a.v * b.v - c.v};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> fnmadd(vlane<T, B> a, vlane<T, B> b, vlane<T, B> c) {
  return {c.v - a.v * b.v};
}
// |a| by clearing the sign bit, as the vector ISAs do (andnot): −0 gives +0, a NaN stays a NaN.
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> abs(vlane<T, B> a) {
  const B mag = ~(B(1) << (sizeof(B) * 8 - 1));
  return {std::bit_cast<T>(B(std::bit_cast<B>(a.v) & mag))};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> sign_bit(vlane<T, B> a) {
  const B sign = B(1) << (sizeof(B) * 8 - 1);
  return {std::bit_cast<T>(B(std::bit_cast<B>(a.v) & sign))};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> xor_bits(vlane<T, B> a, vlane<T, B> b) {
  return {std::bit_cast<T>(B(std::bit_cast<B>(a.v) ^ std::bit_cast<B>(b.v)))};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> and_bits(vlane<T, B> a, vlane<T, B> b) {
  return {std::bit_cast<T>(B(std::bit_cast<B>(a.v) & std::bit_cast<B>(b.v)))};
}
// a with its sign flipped where s is negative
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> xor_sign(vlane<T, B> a, vlane<T, B> s) {
  return xor_bits(a, sign_bit(s));
}
// ±1 with the sign of s (multiplying by it flips where xor_sign(·, s) would)
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> sign_one(vlane<T, B> s) {
  return {std::bit_cast<T>(B(std::bit_cast<B>(sign_bit(s).v) | std::bit_cast<B>(T(1))))};
}
// C++ comparisons are ordered: false whenever either side is NaN.
template <typename T, typename B>
RAYVEC_INLINE vmask operator>=(vlane<T, B> a, vlane<T, B> b) {
  return {a.v >= b.v};
}
template <typename T, typename B>
RAYVEC_INLINE vmask operator<=(vlane<T, B> a, vlane<T, B> b) {
  return {a.v <= b.v};
}
template <typename T, typename B>
RAYVEC_INLINE vmask operator>(vlane<T, B> a, vlane<T, B> b) {
  return {a.v > b.v};
}
template <typename T, typename B>
RAYVEC_INLINE vmask operator<(vlane<T, B> a, vlane<T, B> b) {
  return {a.v < b.v};
}
RAYVEC_INLINE vmask operator&(vmask a, vmask b) { return {a.m && b.m}; }
RAYVEC_INLINE bool any(vmask a) { return a.m; }
RAYVEC_INLINE unsigned bits(vmask a) { return a.m ? 1u : 0u; }
template <typename T, typename B>
RAYVEC_INLINE vmask first_lanes(vlane<T, B>, uint32_t n) {
  return {n > 0};
}
template <typename T, typename B>
RAYVEC_INLINE vmask lanes_between(vlane<T, B>, uint32_t lo, uint32_t hi) {
  return {lo == 0 && hi > 0};
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> select(vmask m, vlane<T, B> a, vlane<T, B> b) {
  return m.m ? b : a;
}

// Min and max by the x86 rule of the vector ISAs: where either is NaN the result is b.
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> vmin(vlane<T, B> a, vlane<T, B> b) {
  return a.v < b.v ? a : b;
}
template <typename T, typename B>
RAYVEC_INLINE vlane<T, B> vmax(vlane<T, B> a, vlane<T, B> b) {
  return a.v > b.v ? a : b;
}

// The smallest lane: the only one.
template <typename T, typename B>
RAYVEC_INLINE T hmin(vlane<T, B> a) {
  return a.v;
}

// Bitwise or of three vectors, and the lanes whose sign bit is clear (+0, positive, +inf, or a NaN
// with a clear sign): the float `mt` pre-test ORs its values and tests the sign once
// (mt_float.inl, mt_sign_pretest).
RAYVEC_INLINE vfloat or3(vfloat a, vfloat b, vfloat c) {
  return {std::bit_cast<float>(std::bit_cast<uint32_t>(a.v) | std::bit_cast<uint32_t>(b.v) |
                               std::bit_cast<uint32_t>(c.v))};
}
RAYVEC_INLINE vmask sign_clear(vfloat a) { return {(std::bit_cast<uint32_t>(a.v) >> 31) == 0}; }
// any(active & sign_clear(a)), the mask left unformed
RAYVEC_INLINE bool any_sign_clear(vmask active, vfloat a) { return any(active & sign_clear(a)); }

}  // namespace rayvec::scalar
