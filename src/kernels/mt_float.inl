// `mt` in float: the arithmetic, one ray's kernels (brute force's, and the leaves the BVH traversals
// call directly) and the any-hit kernel; several rays at once: mt_float_rays.inl. Written once over
// a vector type V (the ISA's vfloat) and compiled per ISA: included by
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
// mt_lower lane by lane.
template <class V>
RAYVEC_INLINE V mt_lower(V tmin) {
  const V zero = V::broadcast(0.0f);
  const V at_zero = select((tmin >= zero) & (tmin <= zero), V::broadcast(-__builtin_inff()), zero);
  return select(tmin > zero, at_zero, tmin * V::broadcast(kMtNarrow));
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
