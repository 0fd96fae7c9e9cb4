// Watertight ray–triangle kernels (Woop, Benthin & Wald 2013, "Watertight Ray/Triangle
// Intersection", JCGT 2(1)), written once over a vector type V (vfloat → `watertight`, vdouble →
// `watertight64`). Included by triangle_kernels_<isa>.cpp after moller_trumbore.inl, inside namespace
// rayvec::<isa>; reuses its LaneHits<V> and next_up(). No std:: calls (ISA-unit rule).
//
// Per ray: kz = the axis of largest |d|, kx, ky the next two (swapped when d[kz] < 0 to keep the
// winding), shear Sx = dx/dz, Sy = dy/dz, Sz = 1/dz. Per triangle: translate the exact vertices
// v0, v1, v2 (never the rounded edges e1, e2) to the ray origin, shear into ray space, and evaluate
// the 2D edge functions U, V, W. A vertex shared by two triangles is transformed by the same
// operations in both, and a shared edge's function is the exact negation in the neighbour
// (a·b − c·d vs c·d − a·b), so no ray slips between them: watertight.
//
// Departures from the paper: the permutation is applied by choosing the coordinate ARRAYS once per
// ray (loads read the permuted coordinates directly, no shuffles); the closed-edge sign test is
// written as "every edge function has the sign of det" (equivalent, NaN-safe with ordered
// compares); t = T/|det| is one correctly rounded division, then tested against the ray's closed
// [tmin, tmax] window like the other intersectors; det must be finite (an Inf vertex never hits);
// no FMA anywhere, so the result is bit-identical on every ISA. The double fallback (an edge
// function that is exactly 0 in float is recomputed in double, where the products of floats are
// exact) is done per lane in scalar code — it is rare — and only for lanes that still pass the
// sign test: a nonzero float edge function already has the exact sign (float rounding is monotone),
// so only zeros can change the answer.

// a·b rounded to V's precision and kept apart from any add that follows: GCC contracts a·b − c·d
// into an FMA in C++ (-ffp-contract=fast is its default there), which would break the exact
// negation of shared edges and make AVX results differ from scalar ones. The empty asm is free.
template <class V>
RAYVEC_INLINE V mul_rounded(V a, V b) {
  V p = a * b;
  __asm__("" : "+x"(p.v));
  return p;
}

// The ray in ray space: which arrays hold the permuted coordinates, and the broadcast shear.
template <class V>
struct WatertightRay {
  const float *ax, *ay, *az, *bx, *by, *bz, *cx, *cy, *cz;  // v0, v1, v2 permuted (kx, ky, kz)
  V ox, oy, oz;                                             // origin, permuted
  V sx, sy, sz;                                             // shear: Sx, Sy, Sz of the paper
  V tmin;
};

template <class V>
RAYVEC_INLINE WatertightRay<V> watertight_ray(const TriangleArrays& T, const Ray& r) {
  using S = typename V::Scalar;
  const float d[3] = {r.dir.x, r.dir.y, r.dir.z};
  const float o[3] = {r.org.x, r.org.y, r.org.z};
  const float ad[3] = {d[0] < 0 ? -d[0] : d[0], d[1] < 0 ? -d[1] : d[1], d[2] < 0 ? -d[2] : d[2]};
  // permutation: kz = axis of largest |d|; swap kx, ky when d[kz] < 0 (keeps the winding)
  int kz = ad[0] > ad[1] ? (ad[0] > ad[2] ? 0 : 2) : (ad[1] > ad[2] ? 1 : 2);
  int kx = kz == 2 ? 0 : kz + 1;
  int ky = kx == 2 ? 0 : kx + 1;
  if (d[kz] < 0) {
    const int k = kx;
    kx = ky;
    ky = k;
  }
  const float* const v0[3] = {T.v0x, T.v0y, T.v0z};
  const float* const v1[3] = {T.v1x, T.v1y, T.v1z};
  const float* const v2[3] = {T.v2x, T.v2y, T.v2z};
  // shear constants, in the kernel's precision
  const S dz = S(d[kz]);
  WatertightRay<V> w;
  w.ax = v0[kx];
  w.ay = v0[ky];
  w.az = v0[kz];
  w.bx = v1[kx];
  w.by = v1[ky];
  w.bz = v1[kz];
  w.cx = v2[kx];
  w.cy = v2[ky];
  w.cz = v2[kz];
  w.ox = V::broadcast(S(o[kx]));
  w.oy = V::broadcast(S(o[ky]));
  w.oz = V::broadcast(S(o[kz]));
  w.sx = V::broadcast(S(d[kx]) / dz);
  w.sy = V::broadcast(S(d[ky]) / dz);
  w.sz = V::broadcast(S(1) / dz);
  w.tmin = V::broadcast(S(r.tmin));
  return w;
}

// U, V, W recomputed in double for the lanes in `lanes` (bits) — the paper's fallback for edge
// functions that are exactly 0 in float. Products of two floats are exact in double, so the double
// difference has the exact sign.
template <class V>
RAYVEC_COLD void watertight_refine(unsigned lanes, V ax, V ay, V bx, V by, V cx, V cy, V& u, V& v, V& w) {
  using S = typename V::Scalar;
  constexpr int W = V::W;
  S a_x[W], a_y[W], b_x[W], b_y[W], c_x[W], c_y[W], us[W], vs[W], ws[W];
  ax.store(a_x);
  ay.store(a_y);
  bx.store(b_x);
  by.store(b_y);
  cx.store(c_x);
  cy.store(c_y);
  u.store(us);
  v.store(vs);
  w.store(ws);
  for (; lanes != 0; lanes &= lanes - 1) {
    const int k = __builtin_ctz(lanes);
    const double Ax = a_x[k], Ay = a_y[k], Bx = b_x[k], By = b_y[k], Cx = c_x[k], Cy = c_y[k];
    us[k] = S(Cx * By - Cy * Bx);
    vs[k] = S(Ax * Cy - Ay * Cx);
    ws[k] = S(Bx * Ay - By * Ax);
  }
  u = V::load(us);
  v = V::load(vs);
  w = V::load(ws);
}

// a·b == c·d exactly (a two-product comparison: equal rounded products and equal exact errors).
RAYVEC_INLINE bool same_product(double a, double b, double c, double d) {
  const double p = a * b, q = c * d;
  return p == q && __builtin_fma(a, b, -p) == __builtin_fma(c, d, -q);
}

// True when triangle j has exactly zero area (e1 × e2 = 0 for the exact vertices). Needed because
// shearing rounds a collinear triangle into a sliver of nonzero area in ray space. The differences
// of floats are exact in double unless the coordinates' exponents differ by more than 29. Inline (and
// cold): the BVH units include this file too, for the packet leaf (bvh/watertight_packet_leaf.inl).
inline RAYVEC_COLD bool zero_area(const TriangleArrays& T, uint32_t j) {
  const uint32_t k = slot_offset(j);
  const double e1x = double(T.v1x[k]) - T.v0x[k], e1y = double(T.v1y[k]) - T.v0y[k],
               e1z = double(T.v1z[k]) - T.v0z[k];
  const double e2x = double(T.v2x[k]) - T.v0x[k], e2y = double(T.v2y[k]) - T.v0y[k],
               e2z = double(T.v2z[k]) - T.v0z[k];
  return same_product(e1y, e2z, e1z, e2y) && same_product(e1z, e2x, e1x, e2z) &&
         same_product(e1x, e2y, e1y, e2x);
}

// A bound on the rounding error of t = T/|det| for a lane that passed the edge tests, after the
// analysis of Pharr, Jakob & Humphreys (Physically Based Rendering, 3rd ed., 3.9.6) with one change:
// t = z0 + Σ bᵢ(zᵢ − z0) for the barycentrics bᵢ = eᵢ/det, so the edge functions' error (δe: from the
// translated and sheared x, y; the shear's part scales with the unscaled depths) moves t by at most
// δe·(spread of the depths)/|det| — not by δe·max|z|, which would grow without limit as a triangle shrinks
// and make tiny closed meshes leak. The depth terms: T's sum (3γ3·max|e|·max|z|, with max|e| <= |det| since
// all eᵢ share det's sign), the depths themselves (γ3·max|z|), det's rounding (γ2·t). A hit is reported only
// beyond the bound, so a ray leaving a surface — a shadow or secondary ray offset from its hit point by a few
// ulps, even at a grazing angle — cannot find that surface again at a t that rounding made zero or positive.
template <class V>
RAYVEC_INLINE V watertight_t_error(V ax, V ay, V az, V bx, V by, V bz, V cx, V cy, V cz, V sz, V adet) {
  using S = typename V::Scalar;
  constexpr S eps = S(0x1p-24);  // unit roundoff of float
  auto gamma = [](int n) { return V::broadcast(S(n) * eps / (S(1) - S(n) * eps)); };
  auto max3 = [](V a, V b, V c) { return vmax(vmax(abs(a), abs(b)), abs(c)); };
  const V za = sz * az, zb = sz * bz, zc = sz * cz;
  const V max_z = max3(za, zb, zc), max_x = max3(ax, bx, cx), max_y = max3(ay, by, cy);
  const V spread_z = max3(za - zb, zb - zc, zc - za);
  // the shear's error in x and y is relative to Sx·z with |Sx| <= 1: the unscaled depths bound it
  const V max_dz = max3(az, bz, cz);
  const V delta_x = gamma(5) * (max_x + max_dz), delta_y = gamma(5) * (max_y + max_dz);
  const V delta_e = V::broadcast(S(2)) * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
  return V::broadcast(S(7)) * gamma(3) * max_z + V::broadcast(S(5)) * delta_e * spread_z / adet;
}

// The triangles' vertex rows of one step as lanes: W consecutive slots loaded from slot i (one ray,
// W triangles), or one slot broadcast (bvh/watertight_packet_leaf.inl: W rays, one triangle).
template <class V>
struct WatertightRows {
  uint32_t k;  // slot_offset of the step's first slot
  RAYVEC_INLINE V operator()(const float* row) const { return V::load(row + k); }
};

// The lanes of `m` whose triangle (slot i + lane) has nonzero area.
template <class V>
struct NonzeroAreaLanes {
  const TriangleArrays& T;
  uint32_t i;
  RAYVEC_INLINE typename V::Mask operator()(typename V::Mask m) const {
    float keep[V::W];
    unsigned dropped = 0;
    for (int k = 0; k < V::W; ++k) keep[k] = 1.0f;
    for (unsigned lanes = bits(m); lanes != 0; lanes &= lanes - 1) {
      const int k = __builtin_ctz(lanes);
      if (zero_area(T, i + unsigned(k))) {
        keep[k] = 0.0f;
        dropped = 1;
      }
    }
    return dropped ? m & (V::load(keep) > V::broadcast(typename V::Scalar(0))) : m;
  }
};

// The lanes that hit with tmin <= t < tlimit and t beyond its rounding error (watertight_t_error):
// lane k tests the ray of lane k of `r` against the triangle whose vertices `at` gives in lane k, and
// `nonzero_area` keeps the lanes of a mask whose triangle has nonzero area. The one body of the
// single-ray kernel (below) and the packet leaf, so both give the same bits lane for lane.
template <class V, class At, class NonzeroArea>
RAYVEC_INLINE LaneHits<V> watertight_lanes(const WatertightRay<V>& r, At at, NonzeroArea nonzero_area,
                                           typename V::Mask active, V tlimit) {
  using S = typename V::Scalar;
  LaneHits<V> out;
  // translate to the ray origin (exact vertices), z stays unsheared until needed
  const V az = at(r.az) - r.oz, bz = at(r.bz) - r.oz, cz = at(r.cz) - r.oz;
  // shear into ray space (separate multiply and subtract: the same rounding on every ISA)
  const V ax = (at(r.ax) - r.ox) - mul_rounded(r.sx, az);
  const V ay = (at(r.ay) - r.oy) - mul_rounded(r.sy, az);
  const V bx = (at(r.bx) - r.ox) - mul_rounded(r.sx, bz);
  const V by = (at(r.by) - r.oy) - mul_rounded(r.sy, bz);
  const V cx = (at(r.cx) - r.ox) - mul_rounded(r.sx, cz);
  const V cy = (at(r.cy) - r.oy) - mul_rounded(r.sy, cz);
  // 2D edge functions (no FMA: a shared edge must give the exact negation in the neighbour)
  V u = mul_rounded(cx, by) - mul_rounded(cy, bx);
  V v = mul_rounded(ax, cy) - mul_rounded(ay, cx);
  V w = mul_rounded(bx, ay) - mul_rounded(by, ax);
  const V zero = V::broadcast(S(0));
  // edge tests (closed): every edge function has the sign of det, i.e. not both signs present
  V det = u + v + w;
  V sign = sign_bit(det);
  typename V::Mask pass =
      active & (xor_bits(u, sign) >= zero) & (xor_bits(v, sign) >= zero) & (xor_bits(w, sign) >= zero);
  out.mask = pass;
  if (!any(pass)) return out;
  if constexpr (sizeof(S) == 4) {  // float: refine exact zeros in double (Woop et al. 2013, §3)
    const unsigned zeros = bits(pass) & (bits((u <= zero) & (u >= zero)) | bits((v <= zero) & (v >= zero)) |
                                         bits((w <= zero) & (w >= zero)));
    if (zeros != 0) {
      watertight_refine<V>(zeros, ax, ay, bx, by, cx, cy, u, v, w);
      det = u + v + w;
      sign = sign_bit(det);
      pass = pass & (xor_bits(u, sign) >= zero) & (xor_bits(v, sign) >= zero) & (xor_bits(w, sign) >= zero);
    }
  }
  // det != 0 and finite (ordered compares also drop NaN)
  const V adet = abs(det);
  out.mask = pass & (adet > zero) & (adet < V::broadcast(S(__builtin_inf())));
  if (!any(out.mask)) return out;
  // depth test: t = (U·Az + V·Bz + W·Cz) / det with the scaled z
  const V tn = xor_bits(mul_rounded(u, mul_rounded(r.sz, az)) + mul_rounded(v, mul_rounded(r.sz, bz)) +
                            mul_rounded(w, mul_rounded(r.sz, cz)),
                        sign);
  out.t = tn / adet;
  out.mask = out.mask & (out.t >= r.tmin) & (out.t < tlimit);
  // float only: in double the translated vertices are exact and the rest rounds at 2^-53, far inside
  // the few float ulps by which a secondary ray leaves its surface
  if constexpr (sizeof(S) == 4)
    if (any(out.mask))
      out.mask = out.mask & (out.t > watertight_t_error(ax, ay, az, bx, by, bz, cx, cy, cz, r.sz, adet));
  // zero-area triangles never hit (checked only for the rare lanes that would hit)
  if (any(out.mask)) out.mask = nonzero_area(out.mask);
  if (any(out.mask)) {  // barycentrics of v1 and v2: V and W weight them
    out.u = xor_bits(v, sign) / adet;
    out.v = xor_bits(w, sign) / adet;
  }
  return out;
}

// The lanes of triangles [i, i + W) that the ray hits with tmin <= t < tlimit and t beyond its
// rounding error (watertight_t_error).
template <class V>
RAYVEC_INLINE LaneHits<V> test_watertight(const TriangleArrays& T, const WatertightRay<V>& r, uint32_t i,
                                          typename V::Mask active, V tlimit) {
  return watertight_lanes<V>(r, WatertightRows<V>{slot_offset(i)}, NonzeroAreaLanes<V>{T, i}, active, tlimit);
}

// The closest hit among triangles [begin, end) for the ray `r` was formed from (finite): the body of
// watertight_closest, also called by BVH leaves that form `r` once per ray (bvh/watertight_leaf.inl).
template <class V>
RAYVEC_INLINE void watertight_closest_ray(const TriangleArrays& T, const WatertightRay<V>& r, uint32_t begin,
                                          uint32_t end, const Ray& ray, Hit& hit) {
  using S = typename V::Scalar;
  constexpr int W = V::W;
  const float limit = ray.tmax < hit.t ? ray.tmax : hit.t;
  const S initial = next_up(S(limit));  // lanes still at `initial` have no hit
  V best_t = V::broadcast(initial);
  V best_u = V::broadcast(S(0)), best_v = best_u, best_idx = best_u;
  bool found = false;
  for (uint32_t i = first_step(begin, W); i < end; i += W) {
    const LaneHits<V> h = test_watertight<V>(T, r, i, step_lanes<V>(i, begin, end), best_t);
    if (any(h.mask)) {  // blend nearest t, u, v and triangle index
      best_t = select(h.mask, best_t, h.t);
      best_u = select(h.mask, best_u, h.u);
      best_v = select(h.mask, best_v, h.v);
      best_idx = select(h.mask, best_idx, V::index_bits(i));
      found = true;
    }
  }
  if (!found) return;
  // final lane reduction: nearest t, then lowest id (as closest_impl in moller_trumbore.inl)
  S ts[W], us[W], vs[W];
  int64_t idx[W];
  best_t.store(ts);
  best_u.store(us);
  best_v.store(vs);
  best_idx.store_index(idx);
  int k_best = -1;
  for (int k = 0; k < W; ++k) {
    if (!(ts[k] < initial)) continue;
    if (k_best < 0 || ts[k] < ts[k_best] ||
        (ts[k] == ts[k_best] &&
         T.id[slot_offset(uint32_t(idx[k]))] < T.id[slot_offset(uint32_t(idx[k_best]))]))
      k_best = k;
  }
  if (k_best < 0) return;
  const float t = float(ts[k_best]);
  const int32_t id = T.id[slot_offset(uint32_t(idx[k_best]))];
  if (t < hit.t || (t == hit.t && (hit.tri < 0 || id < hit.tri)))
    hit = Hit{t, float(us[k_best]), float(vs[k_best]), id};
}

template <class V>
void watertight_closest(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  if (!finite_ray(ray)) return;
  watertight_closest_ray<V>(T, watertight_ray<V>(T, ray), begin, end, ray, hit);
}

// Whether any triangle of [begin, end) accepted by `filter` is hit before tlimit = next_up(tmax) by
// the ray `r` was formed from (finite): the body of watertight_occluded, also called by BVH leaves
// that form `r` once per ray.
template <class V>
RAYVEC_INLINE bool watertight_occluded_ray(const TriangleArrays& T, const WatertightRay<V>& r, V tlimit,
                                           uint32_t begin, uint32_t end, const HitFilter* filter) {
  for (uint32_t i = first_step(begin, V::W); i < end; i += V::W) {
    const typename V::Mask m = test_watertight<V>(T, r, i, step_lanes<V>(i, begin, end), tlimit).mask;
    if (!any(m)) continue;
    if (!filter) return true;
    for (unsigned lanes = bits(m); lanes != 0; lanes &= lanes - 1)
      if (!filter->ignore(filter->context, T.id[slot_offset(i + unsigned(__builtin_ctz(lanes)))]))
        return true;
  }
  return false;
}

// The any-hit limit of `ray`: t < next_up(tmax) is t <= tmax.
template <class V>
RAYVEC_INLINE V watertight_any_limit(const Ray& ray) {
  using S = typename V::Scalar;
  return V::broadcast(next_up(S(ray.tmax)));
}

template <class V>
bool watertight_occluded(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray,
                         const HitFilter* filter) {
  if (!finite_ray(ray)) return false;
  return watertight_occluded_ray<V>(T, watertight_ray<V>(T, ray), watertight_any_limit<V>(ray), begin, end,
                                    filter);
}

template <class V, Intersector I>
constexpr TriangleKernels make_watertight_kernels(Isa isa) {
  return TriangleKernels{isa, I, V::W, &watertight_closest<V>, &watertight_occluded<V>};
}
