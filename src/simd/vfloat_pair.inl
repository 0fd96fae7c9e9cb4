// VPair<V>: two registers of a lane type V as one vector of 2·V::W lanes — the ray packets' lanes on
// AVX2 (16 rays in two ymm registers), so that a 4×4 camera tile is one packet there as on AVX-512
// and each node and triangle a packet visits is loaded and decoded once for 16 rays
// (benchmarks.md#decision-avx2-packets-of-16). Every operation applies V's to both halves: lane
// k < V::W lies in `lo`, lane V::W + k in `hi`, and each lane's result is V's bit for bit. No
// intrinsics here: vfloat_<isa>.h provides V; included inside that ISA's namespace after it.

template <class V>
struct VPairMask {
  typename V::Mask lo, hi;
};

template <class V>
struct VPair {
  static constexpr int W = 2 * V::W;
  using Mask = VPairMask<V>;
  using Scalar = typename V::Scalar;
  V lo, hi;

  static RAYVEC_INLINE VPair load(const Scalar* p) { return {V::load(p), V::load(p + V::W)}; }
  static RAYVEC_INLINE VPair load_aligned(const Scalar* p) {
    return {V::load_aligned(p), V::load_aligned(p + V::W)};
  }
  static RAYVEC_INLINE VPair broadcast(Scalar x) { return {V::broadcast(x), V::broadcast(x)}; }
  RAYVEC_INLINE void store(Scalar* out) const {
    lo.store(out);
    hi.store(out + V::W);
  }
};

template <class V>
RAYVEC_INLINE VPair<V> operator+(VPair<V> a, VPair<V> b) {
  return {a.lo + b.lo, a.hi + b.hi};
}
template <class V>
RAYVEC_INLINE VPair<V> operator-(VPair<V> a, VPair<V> b) {
  return {a.lo - b.lo, a.hi - b.hi};
}
template <class V>
RAYVEC_INLINE VPair<V> operator*(VPair<V> a, VPair<V> b) {
  return {a.lo * b.lo, a.hi * b.hi};
}
template <class V>
RAYVEC_INLINE VPair<V> operator/(VPair<V> a, VPair<V> b) {
  return {a.lo / b.lo, a.hi / b.hi};
}
template <class V>
RAYVEC_INLINE VPair<V> fmadd(VPair<V> a, VPair<V> b, VPair<V> c) {
  return {fmadd(a.lo, b.lo, c.lo), fmadd(a.hi, b.hi, c.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> fmsub(VPair<V> a, VPair<V> b, VPair<V> c) {
  return {fmsub(a.lo, b.lo, c.lo), fmsub(a.hi, b.hi, c.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> fnmadd(VPair<V> a, VPair<V> b, VPair<V> c) {
  return {fnmadd(a.lo, b.lo, c.lo), fnmadd(a.hi, b.hi, c.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> abs(VPair<V> a) {
  return {abs(a.lo), abs(a.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> sign_bit(VPair<V> a) {
  return {sign_bit(a.lo), sign_bit(a.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> xor_bits(VPair<V> a, VPair<V> b) {
  return {xor_bits(a.lo, b.lo), xor_bits(a.hi, b.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> and_bits(VPair<V> a, VPair<V> b) {
  return {and_bits(a.lo, b.lo), and_bits(a.hi, b.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> xor_sign(VPair<V> a, VPair<V> s) {
  return {xor_sign(a.lo, s.lo), xor_sign(a.hi, s.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> vmin(VPair<V> a, VPair<V> b) {
  return {vmin(a.lo, b.lo), vmin(a.hi, b.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> vmax(VPair<V> a, VPair<V> b) {
  return {vmax(a.lo, b.lo), vmax(a.hi, b.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> or3(VPair<V> a, VPair<V> b, VPair<V> c) {
  return {or3(a.lo, b.lo, c.lo), or3(a.hi, b.hi, c.hi)};
}
// a·b rounded and kept apart from any add that follows (watertight.inl's mul_rounded, per half).
template <class V>
RAYVEC_INLINE VPair<V> mul_rounded(VPair<V> a, VPair<V> b) {
  return {mul_rounded(a.lo, b.lo), mul_rounded(a.hi, b.hi)};
}

template <class V>
RAYVEC_INLINE VPairMask<V> operator>=(VPair<V> a, VPair<V> b) {
  return {a.lo >= b.lo, a.hi >= b.hi};
}
template <class V>
RAYVEC_INLINE VPairMask<V> operator<=(VPair<V> a, VPair<V> b) {
  return {a.lo <= b.lo, a.hi <= b.hi};
}
template <class V>
RAYVEC_INLINE VPairMask<V> operator>(VPair<V> a, VPair<V> b) {
  return {a.lo > b.lo, a.hi > b.hi};
}
template <class V>
RAYVEC_INLINE VPairMask<V> operator<(VPair<V> a, VPair<V> b) {
  return {a.lo < b.lo, a.hi < b.hi};
}
template <class V>
RAYVEC_INLINE VPairMask<V> operator&(VPairMask<V> a, VPairMask<V> b) {
  return {a.lo & b.lo, a.hi & b.hi};
}
template <class V>
RAYVEC_INLINE bool any(VPairMask<V> m) {
  return any(m.lo) || any(m.hi);
}
template <class V>
RAYVEC_INLINE unsigned bits(VPairMask<V> m) {
  return bits(m.lo) | bits(m.hi) << V::W;
}
template <class V>
RAYVEC_INLINE VPairMask<V> mask_from_bits(VPair<V>, unsigned b) {
  return {mask_from_bits(V{}, b & ((1u << V::W) - 1u)), mask_from_bits(V{}, b >> V::W)};
}
template <class V>
RAYVEC_INLINE VPair<V> select(VPairMask<V> m, VPair<V> a, VPair<V> b) {
  return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)};
}
template <class V>
RAYVEC_INLINE VPair<V> next_up(VPair<V> x) {
  return {next_up(x.lo), next_up(x.hi)};
}
template <class V>
RAYVEC_INLINE VPairMask<V> sign_mask(VPair<V> a) {
  return {sign_mask(a.lo), sign_mask(a.hi)};
}
template <class V>
RAYVEC_INLINE VPairMask<V> sign_clear(VPair<V> a) {
  return {sign_clear(a.lo), sign_clear(a.hi)};
}
template <class V>
RAYVEC_INLINE bool any_sign_clear(VPairMask<V> active, VPair<V> a) {
  return any_sign_clear(active.lo, a.lo) || any_sign_clear(active.hi, a.hi);
}

// The smallest and the largest of v over `lanes` (bit k: lane k; nonzero): the two halves folded
// lane by lane (the lanes outside `lanes` as ±inf), then V's reduction.
template <class V>
RAYVEC_INLINE typename V::Scalar hmin_lanes(VPair<V> v, unsigned lanes) {
  const V none = V::broadcast(__builtin_inff());
  const V lo = select(mask_from_bits(V{}, lanes & ((1u << V::W) - 1u)), none, v.lo);
  const V hi = select(mask_from_bits(V{}, lanes >> V::W), none, v.hi);
  return hmin_lanes(vmin(lo, hi), (1u << V::W) - 1u);
}
template <class V>
RAYVEC_INLINE typename V::Scalar hmax_lanes(VPair<V> v, unsigned lanes) {
  const V none = V::broadcast(-__builtin_inff());
  const V lo = select(mask_from_bits(V{}, lanes & ((1u << V::W) - 1u)), none, v.lo);
  const V hi = select(mask_from_bits(V{}, lanes >> V::W), none, v.hi);
  return hmax_lanes(vmax(lo, hi), (1u << V::W) - 1u);
}
