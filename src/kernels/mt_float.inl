// `mt` in float: the brute-force hot path and the leaf kernels the BVH traversals call directly,
// written once over a vector type V (the ISA's vfloat) and compiled per ISA: included by
// triangle_kernels_<isa>.cpp and bvh_traversal_<isa>.cpp inside namespace rayvec::<isa>, after
// moller_trumbore.inl (whose ray lanes, step masks and reference kernels it uses). No std:: calls
// here, as there.
//
// Möller–Trumbore rewritten with the scalar triple product identities in the form Embree's
// Moeller intersector uses, over the normal ng = e2 × e1 (stored or formed per step: MtNormal) and
// s = v0 − o, c = s × d:
//   det = d · ng,  u·det = −(e2 · c),  v·det = e1 · c,  t·det = s · ng
// — one cross product per ray and triangle instead of two (21 multiply/adds instead of 27). The sign
// of det is folded into the three numerators (division-free, closed edge tests as before). The
// depth test is split: a conservative division-free pre-test t·|det| < best·(1 + 2^-20)·|det|
// (and >= tmin·(1 − 2^-20)·|det|) that every lane which could be nearer passes, then — only for
// steps where a lane passed — the exact t = (t·|det|)/|det| and the exact tmin <= t < best test. So
// the one correctly rounded division is kept, but almost no step pays for it, and u and v are only
// divided once, for the final hit.

template <class V>
struct MtNumerators {
  typename V::Mask mask;  // lanes passing the edge tests and the conservative depth pre-test
  V un, vn, tn, adet;     // −u·|det| (<= 0 on a hit), v·|det|, t·|det| (>= 0), |det|
};

// The unnormalized geometric normal ng = e2 × e1 (Embree's orientation) of a step's triangles, so
// that det = d · ng and t·det = (v0 − o) · ng (21 multiply/adds a test instead of 27). Read from
// TriangleArrays::ng where stored, else formed from the edges (benchmarks.md#decision-normal-budget):
// each component is two products and a difference, rounded as the fill's scalar cross(e2, e1)
// rounds them (no FMA), so stored and formed normals are the same bits. A step shares it between
// all the rays it tests.
template <class V>
struct MtNormal {
  V x, y, z;
};

template <class V>
RAYVEC_INLINE MtNormal<V> mt_normal(V e1x, V e1y, V e1z, V e2x, V e2y, V e2z) {
  return {e2y * e1z - e2z * e1y, e2z * e1x - e2x * e1z, e2x * e1y - e2y * e1x};
}

// Where the float `mt` arithmetic gets its triangle values: W consecutive triangles, one per lane
// (brute force and the single-ray leaf kernel), or one triangle broadcast to every lane (the
// ray-packet leaf kernel, packet_leaf.inl). `at(kRowV0 + a)` gives the lanes of that row, read from
// the slot's v0x position `p` (every row of a block lies a fixed distance from it, triangle_soa.h:
// one pointer live instead of nine row pointers reloaded per step). Both go through
// mt_numerators_core, so a ray gets bit-identical numerators whichever way the lanes are laid out;
// the values are fetched where they are used, as before the split. `at.edge(kRowV2 + a, v0)` gives
// the lanes of e2 (kRowV1 + a: e1), v − v0 by one float subtraction, and `at.normal()` the lanes
// of ng: loaded from the stored rows (StoredNormal) or mt_normal of those edges; the packet kernel
// reads edges and normal from rows it formed once per leaf.
template <class V, bool StoredNormal = false>
struct MtTriangleLanes {
  const float* p;            // T.v0x + slot_offset(i)
  const float* n = nullptr;  // StoredNormal: T.ng + normal_offset(i)
  RAYVEC_INLINE V operator()(uint32_t row) const { return V::load(p + row * kSlotBlock); }
  RAYVEC_INLINE V edge(uint32_t row, V v0) const { return (*this)(row)-v0; }
  RAYVEC_INLINE MtNormal<V> normal() const {
    if constexpr (StoredNormal) return {V::load(n), V::load(n + kSlotBlock), V::load(n + 2 * kSlotBlock)};
    const V v0x = (*this)(kRowV0), v0y = (*this)(kRowV0 + 1), v0z = (*this)(kRowV0 + 2);
    return mt_normal(edge(kRowV1, v0x), edge(kRowV1 + 1, v0y), edge(kRowV1 + 2, v0z), edge(kRowV2, v0x),
                     edge(kRowV2 + 1, v0y), edge(kRowV2 + 2, v0z));
  }
};

// The v0x position of the step after the W-aligned step at slot i, whose position is p: the next W
// slots of the block, or the first slots of the next block. Carried from step to step instead of
// recomputing slot_offset (a shift, a mask, a multiply and an add a step): on AVX-512 one add.
template <class V>
RAYVEC_INLINE const float* next_step(const float* p, uint32_t i) {
  if constexpr (V::W == kSlotBlock)
    return p + kSlotBlockFloats;
  else
    return (i + V::W) % kSlotBlock == 0 ? p + (kSlotBlockFloats - kSlotBlock + V::W) : p + V::W;
}

// Every float `mt` loop's walk over the W-slot steps of [begin, end): `step(at, i, active)` for the
// step at slot i, whose lanes `at` reads (an MtTriangleLanes at v0x position p) — a head step if
// begin is not on a step (lanes before begin masked), the full steps without a lane mask (p
// carried by next_step), the partial last step. Returns true as soon as a step does (an any-hit
// found), else false. Steps are compiled for stored and for formed normals, chosen once per walk.
template <class V, bool StoredNormal, class Step>
RAYVEC_INLINE bool mt_walk(const TriangleArrays& T, uint32_t begin, uint32_t end, const Step& step) {
  constexpr uint32_t W = V::W;
  const auto lanes = [&T](const float* p, uint32_t i) __attribute__((always_inline)) {
    if constexpr (StoredNormal)
      return MtTriangleLanes<V, true>{p, T.ng + normal_offset(i)};
    else
      return MtTriangleLanes<V, false>{p};
  };
  uint32_t i = begin;
  if (i % W != 0 && i < end) {
    const uint32_t head = first_step(i, W);
    if (step(lanes(T.v0x + slot_offset(head), head), head, step_lanes<V>(head, begin, end))) return true;
    i = head + W;
  }
  const float* p = T.v0x + slot_offset(i);
  for (; end - i >= W && i < end; p = next_step<V>(p, i), i += W)
    if (step(lanes(p, i), i, first_lanes(V{}, W))) return true;
  return i < end && step(lanes(p, i), i, first_lanes(V{}, end - i));
}

template <class V, class Step>
RAYVEC_INLINE bool mt_steps(const TriangleArrays& T, uint32_t begin, uint32_t end, const Step& step) {
  if (T.ng) return mt_walk<V, true>(T, begin, end, step);
  return mt_walk<V, false>(T, begin, end, step);
}

// The part of the arithmetic that depends on the ray's origin but not on its direction: s = v0 − o
// and t·det = s · ng (before det's sign is folded in), with the step's normal ng. Rays from one
// origin (a camera's, a visibility study's) share it: the pair kernel forms it once for both rays,
// from the same operations, so each ray's numerators are bit for bit those it gets alone.
template <class V>
struct MtOrigin {
  V sx, sy, sz, tn;
  MtNormal<V> ng;
};

template <class V, class At>
RAYVEC_INLINE MtOrigin<V> mt_origin_values(const At& at, const RayLanes<V>& r, const MtNormal<V>& ng) {
  const V sx = at(kRowV0) - r.ox, sy = at(kRowV0 + 1) - r.oy, sz = at(kRowV0 + 2) - r.oz;
  return {sx, sy, sz, fmadd(sx, ng.x, fmadd(sy, ng.y, sz * ng.z)), ng};
}

template <class V, class At>
RAYVEC_INLINE MtOrigin<V> mt_origin_values(const At& at, const RayLanes<V>& r) {
  return mt_origin_values<V>(at, r, at.normal());
}

// The arithmetic of every float `mt` entry, lane by lane: ray lanes `r` from the origin part `o`
// against the triangle lanes `at` gives — un, vn, tn and |det| only (`mask` is left unset;
// mt_numerators_core and mt_closest_step add their tests).
template <class V, class At>
RAYVEC_INLINE MtNumerators<V> mt_numerator_values(const At& at, const RayLanes<V>& r, const MtOrigin<V>& o) {
  MtNumerators<V> out;
  // c = s × d
  const V cx = fmsub(o.sy, r.dz, o.sz * r.dy);
  const V cy = fmsub(o.sz, r.dx, o.sx * r.dz);
  const V cz = fmsub(o.sx, r.dy, o.sy * r.dx);
  // det = d · ng
  const V det = fmadd(r.dx, o.ng.x, fmadd(r.dy, o.ng.y, r.dz * o.ng.z));
  out.adet = abs(det);
  // numerators with the sign of det folded in; un = −u·|det| (the negation stays in the compares,
  // one xor fewer than folding it)
  // e2 = v2 − v0 and e1 = v1 − v0, one float subtraction each (triangle_soa.h)
  const V v0x = at(kRowV0), v0y = at(kRowV0 + 1), v0z = at(kRowV0 + 2);
  const V e2x = at.edge(kRowV2, v0x), e2y = at.edge(kRowV2 + 1, v0y), e2z = at.edge(kRowV2 + 2, v0z);
  out.un = xor_sign(fmadd(e2x, cx, fmadd(e2y, cy, e2z * cz)), det);
  const V e1x = at.edge(kRowV1, v0x), e1y = at.edge(kRowV1 + 1, v0y), e1z = at.edge(kRowV1 + 2, v0z);
  out.vn = xor_sign(fmadd(e1x, cx, fmadd(e1y, cy, e1z * cz)), det);
  out.tn = xor_sign(o.tn, det);
  return out;
}

template <class V, class At>
RAYVEC_INLINE MtNumerators<V> mt_numerator_values(const At& at, const RayLanes<V>& r) {
  return mt_numerator_values<V>(at, r, mt_origin_values<V>(at, r));
}

// The closed edge tests of numerators `c`: −u·|det| <= 0, v·|det| >= 0, (u + v)·|det| <= |det|;
// ordered compares, so a NaN fails them.
template <class V>
RAYVEC_INLINE typename V::Mask mt_edges(const MtNumerators<V>& c) {
  const V zero = V::broadcast(0.0f);
  return (c.un <= zero) & (c.vn >= zero) & (c.vn - c.un <= c.adet);
}

// The pre-test with ONE mask instruction (MtPretest::sign_bits; benchmarks.md#decision-sign-pretest): on
// AMD's Zen 5 every instruction that writes a mask register competes with the 19 multiplies/FMAs of
// a step for the same two pipes, while adds and bitwise ops have pipes of their own. So the five
// tests are sign bits — u·|det| = 0 − un, v·|det| = vn + 0, (1 − u − v)·|det| = |det| − (u +
// v)·|det|, t·|det| − lo·|det| (t·|det| + 0 for tmin = 0) and hi·|det| − t·|det| must all have a
// clear sign (the +0 turns −0 into +0, so closed edges stay closed) — ORed and tested once.
// Conservative: every lane passing the ordered tests (mt_edges, tmin <= t <= hi) passes it; NaN
// lanes and |det| = 0 may pass too, so the caller must repeat the ordered tests on the rare steps
// where a lane passes (mt_closest_step). neg_lo = −lo (unused when TminZero).
// mt_sign_values: the ORed values whose sign bits the test reads (a lane passes where the sign is
// clear); mt_sign_pretest: the passing lanes as a mask.
template <class V, bool TminZero>
RAYVEC_INLINE V mt_sign_values(const MtNumerators<V>& c, V neg_lo, V hi) {
  const V zero = V::broadcast(0.0f);
  const V u = zero - c.un, v = c.vn + zero;
  const V w = c.adet - (u + v);
  const V low = TminZero ? c.tn + zero : fmadd(neg_lo, c.adet, c.tn);
  const V nearer = fmsub(hi, c.adet, c.tn);
  return or3(or3(u, v, w), low, nearer);
}
template <class V, bool TminZero>
RAYVEC_INLINE typename V::Mask mt_sign_pretest(const MtNumerators<V>& c, typename V::Mask active, V neg_lo,
                                               V hi) {
  return active & sign_clear(mt_sign_values<V, TminZero>(c, neg_lo, hi));
}

// The same pre-test as ordered compares chained through the lane mask (MtPretest::ordered_compares;
// on AVX-512 each compare writes a mask register under the one before): two instructions fewer
// than the sign bits' normalising adds, ORs and test, faster where mask writes are not what limits
// a step (benchmarks.md#decision-sign-pretest).
// Conservative like mt_sign_pretest (tn < hi·|det| holds for every t <= best: hi is widened by
// 2^-20), so the exact stage sees the same lanes; NaN and |det| = 0 already fail here.
template <class V, bool TminZero>
RAYVEC_INLINE typename V::Mask mt_ordered_pretest(const MtNumerators<V>& c, typename V::Mask active, V neg_lo,
                                                  V hi) {
  const V zero = V::broadcast(0.0f);
  const typename V::Mask m = active & mt_edges(c) & (c.tn < hi * c.adet);
  if constexpr (TminZero)
    return m & (c.tn >= zero);
  else
    return m & (fmadd(neg_lo, c.adet, c.tn) >= zero);
}

// A step's pre-test outcome as its loops read it: first whether any lane passes (the early-out of
// almost every step), then, on the rare steps where one does, which lanes. The sign-bit form forms
// its mask only then (any_sign_clear reads the sign bits directly: on AVX2 a vpxor fewer a step).
template <class V>
struct MtSignPre {
  typename V::Mask active;
  V values;  // mt_sign_values
  RAYVEC_INLINE bool passes() const { return any_sign_clear(active, values); }
  RAYVEC_INLINE typename V::Mask lanes() const { return active & sign_clear(values); }
};
template <class V>
struct MtMaskPre {
  typename V::Mask m;
  RAYVEC_INLINE bool passes() const { return any(m); }
  RAYVEC_INLINE typename V::Mask lanes() const { return m; }
};

template <class V, bool TminZero, MtPretest P>
RAYVEC_INLINE auto mt_pretest(const MtNumerators<V>& c, typename V::Mask active, V neg_lo, V hi) {
  if constexpr (P == MtPretest::sign_bits)
    return MtSignPre<V>{active, mt_sign_values<V, TminZero>(c, neg_lo, hi)};
  else
    return MtMaskPre<V>{mt_ordered_pretest<V, TminZero>(c, active, neg_lo, hi)};
}

// Widening factors of the pre-test: 2^-20 covers the float rounding of best·(1 + 2^-20)·|det| and
// of t = tn/|det| (2^-24 each) with room to spare.
inline constexpr float kMtWiden = 1.0f + 0x1p-20f, kMtNarrow = 1.0f - 0x1p-20f;

// The pre-test's lower factor for tmin: every t >= tmin has tn >= lo·|det|.
RAYVEC_INLINE float mt_lower(float tmin) {
  if (tmin > 0.0f) return tmin * kMtNarrow;
  return tmin == 0.0f ? 0.0f : -__builtin_inff();
}

// Per-lane best hit of closest_mt_float, plus the pre-test threshold `hi`, which is shared by all
// lanes: the nearest t found so far in ANY lane, widened. A triangle behind the ray's nearest hit
// can never win, whatever its lane, so sharing the threshold makes the exact stage (and its
// mispredicted branch) run about log(hits) times per ray instead of that many times per lane.
template <class V>
struct MtBest {
  V t, hi, un, vn, adet, idx;
  bool found;
};

// The step at slot i, whose lanes `at` reads (mt_steps), for the ray `r` from the origin part `o`.
template <class V, bool TminZero, MtPretest P, class At>
RAYVEC_INLINE void mt_closest_step(const At& at, uint32_t i, const RayLanes<V>& r, const MtOrigin<V>& o,
                                   typename V::Mask active, V neg_lo, MtBest<V>& b) {
  const MtNumerators<V> c = mt_numerator_values<V>(at, r, o);
  const auto pre = mt_pretest<V, TminZero, P>(c, active, neg_lo, b.hi);
  if (!pre.passes()) return;
  // the ordered tests (NaN and |det| = 0 fail them) and the exact depth test, only for steps where
  // a lane may be nearer; ties go to the lower id later
  const V t = c.tn / c.adet;
  const typename V::Mask m =
      pre.lanes() & mt_edges(c) & (c.adet > V::broadcast(0.0f)) & (t >= r.tmin) & (t < b.t);
  if (!any(m)) return;
  b.t = select(m, b.t, t);
  b.un = select(m, b.un, c.un);
  b.vn = select(m, b.vn, c.vn);
  b.adet = select(m, b.adet, c.adet);
  b.idx = select(m, b.idx, V::index_bits(i));
  b.hi = V::broadcast(hmin(b.t) * kMtWiden);
  b.found = true;
}

// The winner among the lanes of `b` (nearest t, then lowest id) replaces `hit` if nearer; u and v
// are divided once, here. The nearest t is one lane reduction; only when several lanes hold it
// are their ids compared (lanes without a hit still hold `initial`, above every hit, and no lane
// holds NaN: a t is kept only after ordered compares).
template <class V>
RAYVEC_INLINE void mt_finish(const TriangleArrays& T, const MtBest<V>& b, float initial, Hit& hit) {
  constexpr int W = V::W;
  if (!b.found) return;
  const float t = hmin(b.t);
  if (!(t < initial)) return;
  float us[W], vs[W], as[W];
  int64_t idx[W];
  b.un.store(us);
  b.vn.store(vs);
  b.adet.store(as);
  b.idx.store_index(idx);
  unsigned nearest = bits(b.t <= V::broadcast(t));
  int k_best = __builtin_ctz(nearest);
  for (nearest &= nearest - 1; nearest != 0; nearest &= nearest - 1) {  // a tie: the lowest id
    const int k = __builtin_ctz(nearest);
    if (T.id[slot_offset(uint32_t(idx[k]))] < T.id[slot_offset(uint32_t(idx[k_best]))]) k_best = k;
  }
  const int32_t id = T.id[slot_offset(uint32_t(idx[k_best]))];
  // t + 0: of lanes tied at t = ±0, hmin returns either sign; +0 always, so every layout (lanes,
  // ray packets) reports the same bits. 0 − un: no −0 either.
  if (t < hit.t || (t == hit.t && (hit.tri < 0 || id < hit.tri)))
    hit = Hit{t + 0.0f, (0.0f - us[k_best]) / as[k_best], vs[k_best] / as[k_best], id};
}

// One ray's constants and running best.
template <class V>
struct MtRay {
  RayLanes<V> r;
  V lo;
  float initial;  // lanes still at `initial` have no hit
  MtBest<V> b;
};

template <class V>
RAYVEC_INLINE MtRay<V> mt_ray(const Ray& ray, const Hit& hit) {
  const float limit = ray.tmax < hit.t ? ray.tmax : hit.t;
  const float initial = next_up(limit);
  const V zero = V::broadcast(0.0f);
  return MtRay<V>{
      broadcast_ray<V>(ray), V::broadcast(mt_lower(ray.tmin)), initial,
      MtBest<V>{V::broadcast(initial), V::broadcast(initial * kMtWiden), zero, zero, zero, zero, false}};
}

// Whether a lane of the step may pass the sign-bit pre-test for any of the R rays from the origin
// part `o`: their sign values ANDed (a lane's sign stays clear where some ray's is), then one test.
// A mask instruction costs a step as much as a multiply where the FMA pipes also write the masks
// (AMD's), and almost every step passes for no ray: one test a step instead of one a ray. Where it
// passes, each ray's step runs as alone (mt_closest_step forms the same numerators again), so every
// ray keeps its bits.
// q[k].r: the rays' lanes; hi(k): their upper factors.
template <class V, bool TminZero, int R, class At, class Q, class Hi>
RAYVEC_INLINE bool mt_any_ray_passes(const At& at, const Q* q, const MtOrigin<V>& o, typename V::Mask active,
                                     const V* neg_lo, const Hi& hi) {
  V some = mt_sign_values<V, TminZero>(mt_numerator_values<V>(at, q[0].r, o), neg_lo[0], hi(0));
#pragma GCC unroll 16
  for (int k = 1; k < R; ++k)
    some =
        and_bits(some, mt_sign_values<V, TminZero>(mt_numerator_values<V>(at, q[k].r, o), neg_lo[k], hi(k)));
  return any_sign_clear(active, some);
}

// The same group test, cheaper where the rays' origin is shared: with s = v0 − o, the numerators
// u·det = −(e2 · (s × d)) and v·det = e1 · (s × d) are also −d · (e2 × s) and d · (e1 × s) (the
// triple product turned around), so the two cross products e2 × s and e1 × s are formed once a
// step for the whole group (MtOriginCross) and each ray pays three dot products (det, u, v): with
// the edge sum and depth tests 11 multiply/adds a ray instead of 16. Rounded differently from the
// per-ray numerators, so u and v are widened by `slack` (mt_crossed_slack), a bound on the
// difference of the two roundings, and the edge sum by 2^-20·|det| and three slacks more: every lane
// that passes a ray's ordered tests (closed edges, tmin <= t < best) passes this one. det and t·det
// are those of the per-ray numerators, bit for bit. Where a lane passes, each ray's step runs as
// alone, as after mt_any_ray_passes.
template <class V>
struct MtOriginCross {
  V ax, ay, az;  // e2 × s
  V bx, by, bz;  // e1 × s
};

template <class V, class At>
RAYVEC_INLINE MtOriginCross<V> mt_origin_cross(const At& at, const MtOrigin<V>& o) {
  const V v0x = at(kRowV0), v0y = at(kRowV0 + 1), v0z = at(kRowV0 + 2);
  const V e2x = at.edge(kRowV2, v0x), e2y = at.edge(kRowV2 + 1, v0y), e2z = at.edge(kRowV2 + 2, v0z);
  const V e1x = at.edge(kRowV1, v0x), e1y = at.edge(kRowV1 + 1, v0y), e1z = at.edge(kRowV1 + 2, v0z);
  return {fmsub(e2y, o.sz, e2z * o.sy), fmsub(e2z, o.sx, e2x * o.sz), fmsub(e2x, o.sy, e2y * o.sx),
          fmsub(e1y, o.sz, e1z * o.sy), fmsub(e1z, o.sx, e1x * o.sz), fmsub(e1x, o.sy, e1y * o.sx)};
}

// The values whose sign bits the crossed test reads for the ray `r` (clear: the lane may pass):
// u and v each within slack/2 of the ray's own u·|det| and v·|det| before their slack is added (so
// at least slack/2 above zero where those pass, at most 1.5·slack above them); the edge sum
// |det|·(1 + 2^-20) + 5·slack − u − v then stays above zero wherever the ray's own (v − u)·|det| <=
// |det| holds, its roundings (a few 2^-24 of |det| and of the slacks) inside the 2^-20·|det| and
// the two spare slacks; the depth values are the per-ray pre-test's (mt_sign_values).
template <class V, bool TminZero>
RAYVEC_INLINE V mt_crossed_sign_values(const RayLanes<V>& r, const MtOrigin<V>& o, const MtOriginCross<V>& x,
                                       V slack, V slack5, V neg_lo, V hi) {
  const V zero = V::broadcast(0.0f);
  const V det = fmadd(r.dx, o.ng.x, fmadd(r.dy, o.ng.y, r.dz * o.ng.z));  // as mt_numerator_values
  const V adet = abs(det);
  const V u = slack - xor_sign(fmadd(r.dx, x.ax, fmadd(r.dy, x.ay, r.dz * x.az)), det);
  const V v = xor_sign(fmadd(r.dx, x.bx, fmadd(r.dy, x.by, r.dz * x.bz)), det) + slack;
  const V w = fmadd(adet, V::broadcast(kMtWiden), slack5) - (u + v);
  const V tn = xor_sign(o.tn, det);
  const V low = TminZero ? tn + zero : fmadd(neg_lo, adet, tn);
  const V nearer = fmsub(hi, adet, tn);
  return or3(or3(u, v, w), low, nearer);
}

template <class V, bool TminZero, int R, class At, class Q, class Hi>
RAYVEC_INLINE bool mt_any_ray_passes_crossed(const At& at, const Q* q, const MtOrigin<V>& o,
                                             typename V::Mask active, V slack, const V* neg_lo,
                                             const Hi& hi) {
  const MtOriginCross<V> x = mt_origin_cross<V>(at, o);
  const V slack5 = slack * V::broadcast(5.0f);
  V some = mt_crossed_sign_values<V, TminZero>(q[0].r, o, x, slack, slack5, neg_lo[0], hi(0));
#pragma GCC unroll 16
  for (int k = 1; k < R; ++k)
    some = and_bits(some, mt_crossed_sign_values<V, TminZero>(q[k].r, o, x, slack, slack5, neg_lo[k], hi(k)));
  return any_sign_clear(active, some);
}

// The crossed test's slack for the n rays from one origin: a bound on how far its u·det and v·det
// can lie from the per-ray ones. Each is a cross product and a dot product over |e| <= 2·B, |s| <=
// B + |o| and |d| <= D (B the mesh's coordinate bound; componentwise maxima), and each rounds within
// 30·2^-24·|e|·|s|·|d| of the exact triple product (a cross component: two roundings of at most
// 2·|s|·|d|; the dot: three roundings of sums up to 3·|e|·2·|s|·|d|, plus the cross components'
// errors times |e|): together within 120·2^-24·B·(B + |o|)·D < 2^-17·B·(B + |o|)·D. Twice that,
// plus 2^-100 for the absolute errors of underflow, rounded up to a float. Negative where the
// products could overflow (a coordinate not finite, or B·(B + |o|)·max(D, 1) near 2^128): the
// group then takes the per-ray tests, four rays at a time.
// ray(k): the k-th ray of the group.
template <class RayAt>
RAYVEC_INLINE float mt_crossed_slack(const TriangleArrays& T, int n, const RayAt& ray) {
  const auto mag = [](float x) { return double(x < 0.0f ? -x : x); };
  const auto max3 = [&](const Vec3f& v) {
    const double a = mag(v.x), b = mag(v.y), c = mag(v.z);
    return a > b ? (a > c ? a : c) : (b > c ? b : c);
  };
  const double b = T.coord_bound, o = max3(ray(0).org);
  double d = 0.0;
  for (int k = 0; k < n; ++k) {
    const double dk = max3(ray(k).dir);
    d = dk > d ? dk : d;
  }
  if (!(b <= 0x1p100) || !(b * (b + o) * (d > 1.0 ? d : 1.0) < 0x1p110)) return -1.0f;
  return float((b * (b + o) * d * 0x1p-16 + 0x1p-100) * (1.0 + 0x1p-20));
}

// Each ray's step of the rare steps that pass mt_any_ray_passes, out of line: inlined, g++ keeps the
// fast path's numerators of every ray for it (spilled to the stack at every step).
template <class V, bool TminZero, int R, MtPretest P, class At>
[[gnu::noinline, gnu::cold]] void mt_closest_steps(const At& at, uint32_t i, MtRay<V>* q,
                                                   const MtOrigin<V>& o, typename V::Mask active,
                                                   const V* neg_lo) {
  for (int k = 0; k < R; ++k) mt_closest_step<V, TminZero, P>(at, i, q[k].r, o, active, neg_lo[k], q[k].b);
}

// R rays (1, 2, 4, 8 or 16) against [begin, end): each triangle step is loaded once for all R rays. With
// SharedOrigin (the rays' origins equal bit for bit) the origin part of each step is formed once.
// Crossed (with SharedOrigin): the group test mt_any_ray_passes_crossed, widened by `slack`
// (mt_crossed_slack), whichever pre-test P the rays' own steps take.
template <class V, bool TminZero, int R, MtPretest P = MtPretest::sign_bits, bool SharedOrigin = false,
          bool Crossed = false>
void closest_mt_float_rays(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays, Hit* hits,
                           float slack = 0.0f) {
  const V vslack = V::broadcast(slack);
  MtRay<V> q[R];
  V neg_lo[R];  // −lo, for mt_sign_pretest's fused t·|det| − lo·|det|
  for (int k = 0; k < R; ++k) {
    q[k] = mt_ray<V>(rays[k], hits[k]);
    neg_lo[k] = V::broadcast(0.0f) - q[k].lo;
  }
  mt_steps<V>(
      T, begin, end, [&](const auto& at, uint32_t i, typename V::Mask active) __attribute__((always_inline)) {
        if constexpr (SharedOrigin) {
          // the rays' steps unrolled: left a loop (g++ does for four rays and more), each ray's lanes
          // and best hit are reloaded from memory at every step
          const MtOrigin<V> o = mt_origin_values<V>(at, q[0].r);
          if constexpr (Crossed || P == MtPretest::sign_bits) {
            const auto hi = [&](int k) __attribute__((always_inline)) { return q[k].b.hi; };
            if (Crossed ? mt_any_ray_passes_crossed<V, TminZero, R>(at, q, o, active, vslack, neg_lo, hi)
                        : mt_any_ray_passes<V, TminZero, R>(at, q, o, active, neg_lo, hi))
              mt_closest_steps<V, TminZero, R, P>(at, i, q, o, active, neg_lo);
            return false;
          }
#pragma GCC unroll 8
          for (int k = 0; k < R; ++k)
            mt_closest_step<V, TminZero, P>(at, i, q[k].r, o, active, neg_lo[k], q[k].b);
        } else {
          const MtNormal<V> ng = at.normal();  // once for the R rays
          for (int k = 0; k < R; ++k)
            mt_closest_step<V, TminZero, P>(at, i, q[k].r, mt_origin_values<V>(at, q[k].r, ng), active,
                                            neg_lo[k], q[k].b);
        }
        return false;
      });
  for (int k = 0; k < R; ++k) mt_finish<V>(T, q[k].b, q[k].initial, hits[k]);
}

// One ray against [begin, end), the winner kept as scalars: a step where a lane passes the exact
// test is reduced at once (its nearest t by one hmin; of equal t its lowest lane, the lowest id, as
// ids increase in a range), and later steps accept only t below it — a later step holds higher
// ids, so a tie keeps the earlier hit. Same hit as closest_mt_float_rays (whose per-lane best
// vectors are reduced at the end), but only the ray's lanes and the pre-test threshold stay live
// across steps: the single-ray leaf then fits AVX2's 16 vector registers without spilling them.
// Always inlined, for the traversals of large trees that inline their leaves (LeafCall::inlined);
// closest_mt_float_one is the same kernel as a function of its own.
template <class V, bool TminZero, MtPretest P = MtPretest::sign_bits>
RAYVEC_INLINE void closest_mt_float_one_inline(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                               const Ray& ray, Hit& hit) {
  constexpr uint32_t W = V::W;
  const RayLanes<V> r = broadcast_ray<V>(ray);
  const float limit = ray.tmax < hit.t ? ray.tmax : hit.t;
  const float initial = next_up(limit);  // best while nothing is found: accepts t <= limit
  float best = initial, un = 0.0f, vn = 0.0f, adet = 0.0f;
  uint32_t winner = 0;
  V hi = V::broadcast(initial * kMtWiden);
  const V neg_lo = V::broadcast(0.0f) - V::broadcast(mt_lower(ray.tmin));
  const auto step = [&](const auto& at, uint32_t i, typename V::Mask active) __attribute__((always_inline)) {
    const MtNumerators<V> c = mt_numerator_values<V>(at, r);
    const auto pre = mt_pretest<V, TminZero, P>(c, active, neg_lo, hi);
    if (!pre.passes()) return false;
    const V t = c.tn / c.adet;
    const typename V::Mask m =
        pre.lanes() & mt_edges(c) & (c.adet > V::broadcast(0.0f)) & (t >= r.tmin) & (t < V::broadcast(best));
    if (!any(m)) return false;
    best = hmin(select(m, V::broadcast(__builtin_inff()), t));
    const unsigned k = unsigned(__builtin_ctz(bits(m & (t <= V::broadcast(best)))));
    alignas(64) float us[W], vs[W], as[W];
    c.un.store(us);
    c.vn.store(vs);
    c.adet.store(as);
    un = us[k];
    vn = vs[k];
    adet = as[k];
    winner = i + k;
    hi = V::broadcast(best * kMtWiden);
    return false;
  };
  mt_steps<V>(T, begin, end, step);
  if (!(best < initial)) return;
  const int32_t id = T.id[slot_offset(winner)];
  if (best < hit.t || (best == hit.t && (hit.tri < 0 || id < hit.tri)))
    hit = Hit{best + 0.0f, (0.0f - un) / adet, vn / adet, id};  // as mt_finish: no −0
}

template <class V, bool TminZero, MtPretest P = MtPretest::sign_bits>
void closest_mt_float_one(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  closest_mt_float_one_inline<V, TminZero, P>(T, begin, end, ray, hit);
}

// tmin = 0 (camera and most secondary rays) drops the multiply of the lower depth pre-test.
template <class V, MtPretest P = MtPretest::sign_bits>
void closest_mt_float(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  if (!finite_ray(ray)) return;
  if (ray.tmin == 0.0f)
    closest_mt_float_one<V, true, P>(T, begin, end, ray, hit);
  else
    closest_mt_float_one<V, false, P>(T, begin, end, ray, hit);
}

// One ray's constants of the float `mt` any-hit kernel: its lanes, the pre-test's lower and upper
// factors and the exact upper bound, formed once per ray — by each table call, or once per
// traversal when a BVH unit calls the leaf kernel directly with these lanes in memory
// (bvh/mt_any_hit_leaf.inl; benchmarks.md#decision-any-hit-leaf-lanes).
template <class V>
struct MtAnyHitRay {
  RayLanes<V> r;
  V lo, hi, tlimit;
};

template <class V>
RAYVEC_INLINE MtAnyHitRay<V> mt_any_hit_ray(const Ray& ray) {
  const float limit = next_up(ray.tmax);
  return {broadcast_ray<V>(ray), V::broadcast(mt_lower(ray.tmin)), V::broadcast(limit * kMtWiden),
          V::broadcast(limit)};
}

// The any-hit tests of one step's numerators `c` (mt_numerator_values, lanes `active`) for the ray
// `q`: true when a lane holds a hit that `filter` (may be null) accepts. First the division-free
// pre-test as ordered compares — closed edges, lo·|det| <= t·|det| < hi·|det| (|det| = 0 fails:
// t·|det| >= 0 and < 0 cannot both hold; NaN fails every compare) — then, for a step where a lane
// passes, the exact tmin <= t < tlimit.
// mt_any_hit_lanes: the lanes of `active` that hold a hit, before any filter — also the test of
// the packet any-hit leaf (bvh/packet_leaf.inl), whose lanes are rays and `q` a packet's.
template <class V>
RAYVEC_INLINE typename V::Mask mt_any_hit_lanes(const MtNumerators<V>& c, typename V::Mask active,
                                                const MtAnyHitRay<V>& q) {
  const typename V::Mask m = active & mt_edges(c) & (c.tn < q.hi * c.adet) & (c.tn >= q.lo * c.adet);
  if (!any(m)) return m;
  const V t = c.tn / c.adet;
  return m & (t >= q.r.tmin) & (t < q.tlimit);
}

template <class V>
RAYVEC_INLINE bool mt_any_hit_step(const TriangleArrays& T, uint32_t i, const MtNumerators<V>& c,
                                   typename V::Mask active, const MtAnyHitRay<V>& q,
                                   const HitFilter* filter) {
  const typename V::Mask m = mt_any_hit_lanes<V>(c, active, q);
  if (!any(m)) return false;
  if (!filter) return true;
  for (unsigned lanes = bits(m); lanes != 0; lanes &= lanes - 1)
    if (!filter->ignore(filter->context, T.id[slot_offset(i + unsigned(__builtin_ctz(lanes)))])) return true;
  return false;
}

// Any hit of the ray `q` (finite origin and direction, no NaN interval) in [begin, end) accepted by
// `filter` (may be null).
template <class V>
RAYVEC_INLINE bool occluded_mt_float_lanes(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                           const MtAnyHitRay<V>& q, const HitFilter* filter) {
  const auto step = [&](const auto& at, uint32_t i, typename V::Mask active) __attribute__((always_inline)) {
    return mt_any_hit_step<V>(T, i, mt_numerator_values<V>(at, q.r), active, q, filter);
  };
  return mt_steps<V>(T, begin, end, step);
}

template <class V>
bool occluded_mt_float(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray,
                       const HitFilter* filter) {
  if (!finite_ray(ray)) return false;
  return occluded_mt_float_lanes<V>(T, begin, end, mt_any_hit_ray<V>(ray), filter);
}
