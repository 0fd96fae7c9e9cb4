// The float `mt` kernel for R rays at once (closest_mt_float_rays): each triangle step loaded once
// for all of them, and for rays from one origin its origin part formed once and a group test (the
// sign bits ANDed over the rays, or the crossed test with the cross products formed once a step)
// that settles almost every step for the whole group in one test: no ray can hit there. Every ray
// gets bit for bit the hit it gets alone. Written once over a vector type V and compiled per ISA:
// included by triangle_kernels_<isa>.cpp (for mt_float_groups.inl's tables) and
// bvh_traversal_avx512.cpp (its single-ray leaf, R = 1) inside namespace rayvec::<isa>, after
// mt_float.inl, whose arithmetic it uses. No std:: calls here, as there.

// Per-lane best hit of closest_mt_float_rays, plus the pre-test threshold `hi`, which is shared by all
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
// det's orientation goes in one of two ways, the same bits either way (s·x is exact for s = ±1): as
// xor_sign and an add or subtract, or with FusedSign as an FMA by det's sign as ±1 (sign_one) — two
// instructions fewer a ray, all of them FMAs. The first suits a core with pipes for adds and bitwise
// operations beside its FMA pipes, the second one whose vector operations all share the FMA ports
// (benchmarks.md#decision-fused-sign). Each form is written out whole, tail included: sharing the
// tail changes how g++ schedules the sign-bit form, which stays as measured.
template <class V, bool TminZero, bool FusedSign>
RAYVEC_INLINE V mt_crossed_sign_values(const RayLanes<V>& r, const MtOrigin<V>& o, const MtOriginCross<V>& x,
                                       V slack, V slack5, V neg_lo, V hi) {
  const V zero = V::broadcast(0.0f);
  const V det = fmadd(r.dx, o.ng.x, fmadd(r.dy, o.ng.y, r.dz * o.ng.z));  // as mt_numerator_values
  const V adet = abs(det);
  if constexpr (FusedSign) {
    const V un = fmadd(r.dx, x.ax, fmadd(r.dy, x.ay, r.dz * x.az)),
            vn = fmadd(r.dx, x.bx, fmadd(r.dy, x.by, r.dz * x.bz));
    const V s = sign_one(det);
    const V u = fnmadd(s, un, slack), v = fmadd(s, vn, slack);
    const V w = fmadd(adet, V::broadcast(kMtWiden), slack5) - (u + v);
    // with TminZero, −0 made +0 as the add below does
    const V tn = TminZero ? fmadd(s, o.tn, zero) : s * o.tn;
    const V low = TminZero ? tn : fmadd(neg_lo, adet, tn);
    const V nearer = fmsub(hi, adet, tn);
    return or3(or3(u, v, w), low, nearer);
  }
  const V u = slack - xor_sign(fmadd(r.dx, x.ax, fmadd(r.dy, x.ay, r.dz * x.az)), det);
  const V v = xor_sign(fmadd(r.dx, x.bx, fmadd(r.dy, x.by, r.dz * x.bz)), det) + slack;
  const V w = fmadd(adet, V::broadcast(kMtWiden), slack5) - (u + v);
  const V tn = xor_sign(o.tn, det);
  const V low = TminZero ? tn + zero : fmadd(neg_lo, adet, tn);
  const V nearer = fmsub(hi, adet, tn);
  return or3(or3(u, v, w), low, nearer);
}

template <class V, bool TminZero, int R, MtPretest P, class At, class Q, class Hi>
RAYVEC_INLINE bool mt_any_ray_passes_crossed(const At& at, const Q* q, const MtOrigin<V>& o,
                                             typename V::Mask active, V slack, const V* neg_lo,
                                             const Hi& hi) {
  // the fused sign with the ordered pre-test's table: both are the choices for Intel's ports
  constexpr bool kFused = P == MtPretest::ordered_compares;
  const MtOriginCross<V> x = mt_origin_cross<V>(at, o);
  const V slack5 = slack * V::broadcast(5.0f);
  V some = mt_crossed_sign_values<V, TminZero, kFused>(q[0].r, o, x, slack, slack5, neg_lo[0], hi(0));
#pragma GCC unroll 16
  for (int k = 1; k < R; ++k)
    some = and_bits(
        some, mt_crossed_sign_values<V, TminZero, kFused>(q[k].r, o, x, slack, slack5, neg_lo[k], hi(k)));
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
            bool passes;
            if constexpr (Crossed)
              passes = mt_any_ray_passes_crossed<V, TminZero, R, P>(at, q, o, active, vslack, neg_lo, hi);
            else
              passes = mt_any_ray_passes<V, TminZero, R>(at, q, o, active, neg_lo, hi);
            if (passes) mt_closest_steps<V, TminZero, R, P>(at, i, q, o, active, neg_lo);
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
