// The ray–triangle kernel body, written once over a vector type V (vfloat or vdouble of the ISA) and
// compiled per ISA: triangle_kernels_<isa>.cpp (and bvh_traversal_<isa>.cpp, for the leaves)
// includes this inside namespace rayvec::<isa>, after that ISA's simd header. No std:: calls here —
// ISA units must not instantiate inline code shared with baseline units.
//
// Follows Sena, Sampaio, Nascimento & Nery (2018): one ray broadcast to all lanes, W triangles of the
// SoA arrays per step, masks with early-outs, blend of the nearest t and triangle index per lane,
// a final lane reduction. Departures: blocked rows of v0, v1, v2 (edges formed per step), FMA, a
// division-free barycentric test (the sign of det folded into u and v) with one correctly rounded
// division for t only when a lane survives, u and v tracked per lane, ordered comparisons so NaN never hits,
// and ties resolved towards the lower triangle id. The float `mt` path (closest_mt_float, mt_float.inl) goes
// further: the normal ng = e2 × e1 shared by the rays of a step, a conservative division-free depth pre-test
// against the nearest hit of any lane, divisions only for the final hit, and several rays per triangle load
// (closest_group). Each choice and what it measured: benchmarks.md#decision-precomputed-normal,
// #decision-depth-pretest, #decision-early-outs, #decision-fma and #decision-rays-per-triangle-load.

template <class V>
struct RayLanes {
  V ox, oy, oz, dx, dy, dz, tmin;
};

template <class V>
RAYVEC_INLINE RayLanes<V> broadcast_ray(const Ray& r) {
  using S = typename V::Scalar;
  return {V::broadcast(S(r.org.x)), V::broadcast(S(r.org.y)), V::broadcast(S(r.org.z)),
          V::broadcast(S(r.dir.x)), V::broadcast(S(r.dir.y)), V::broadcast(S(r.dir.z)),
          V::broadcast(S(r.tmin))};
}

// False when the ray can never hit: a NaN or Inf in its origin or direction, or NaN tmin/tmax.
RAYVEC_INLINE bool finite_ray(const Ray& r) {
  const float big = 3.4028235e38f;
  const float c[6] = {r.org.x, r.org.y, r.org.z, r.dir.x, r.dir.y, r.dir.z};
  for (float x : c)
    if (!(x >= -big && x <= big)) return false;
  return r.tmin == r.tmin && r.tmax == r.tmax;
}

// Whether a and b are the same bits (so −0 and +0 differ: v0 − o then rounds alike for both).
RAYVEC_INLINE bool same_bits(const Vec3f& a, const Vec3f& b) {
  return __builtin_bit_cast(uint32_t, a.x) == __builtin_bit_cast(uint32_t, b.x) &&
         __builtin_bit_cast(uint32_t, a.y) == __builtin_bit_cast(uint32_t, b.y) &&
         __builtin_bit_cast(uint32_t, a.z) == __builtin_bit_cast(uint32_t, b.z);
}

// The smallest value greater than x (x itself for +inf and NaN), so `t < next_up(x)` means t <= x.
RAYVEC_INLINE float next_up(float x) {
  if (!(x == x) || x == __builtin_inff()) return x;
  if (x == 0.0f) return __builtin_bit_cast(float, 1u);
  uint32_t b = __builtin_bit_cast(uint32_t, x);
  b = x > 0.0f ? b + 1 : b - 1;
  return __builtin_bit_cast(float, b);
}
RAYVEC_INLINE double next_up(double x) {
  if (!(x == x) || x == __builtin_inf()) return x;
  if (x == 0.0) return __builtin_bit_cast(double, uint64_t(1));
  uint64_t b = __builtin_bit_cast(uint64_t, x);
  b = x > 0.0 ? b + 1 : b - 1;
  return __builtin_bit_cast(double, b);
}

// Blocked rows (triangle_soa.h): a step loads W lanes from a slot that is a multiple of W, so the
// steps of [begin, end) start at begin rounded down, and step_lanes masks the lanes outside the
// range (those below begin only in that first step).
RAYVEC_INLINE uint32_t first_step(uint32_t begin, uint32_t W) { return begin - begin % W; }
template <class V>
RAYVEC_INLINE typename V::Mask step_lanes(uint32_t i, uint32_t begin, uint32_t end) {
  return i >= begin ? first_lanes(V{}, end - i) : lanes_between(V{}, begin - i, end - i);
}

// The lanes of one step that hit, with their t, u, v.
template <class V>
struct LaneHits {
  typename V::Mask mask;
  V t, u, v;
};

// Sena et al. (2018) Figure 4 arithmetic, unchanged: multiplies and adds rounded separately,
// f = 1/det, |det| >= 1e-6, t > 1e-6; plus the ray's [tmin, tmax] window.
template <class V>
RAYVEC_INLINE LaneHits<V> test_paper(const TriangleArrays& T, uint32_t i, const RayLanes<V>& r,
                                     typename V::Mask active, V tlimit) {
  LaneHits<V> out;
  const uint32_t k = slot_offset(i);  // the step's lanes in each row (blocked rows)
  const V v0x = V::load(T.v0x + k), v0y = V::load(T.v0y + k), v0z = V::load(T.v0z + k);
  const V e1x = V::load(T.v1x + k) - v0x, e1y = V::load(T.v1y + k) - v0y, e1z = V::load(T.v1z + k) - v0z;
  const V e2x = V::load(T.v2x + k) - v0x, e2y = V::load(T.v2y + k) - v0y, e2z = V::load(T.v2z + k) - v0z;
  // h = d × e2, a = e1 · h
  const V hx = r.dy * e2z - r.dz * e2y, hy = r.dz * e2x - r.dx * e2z, hz = r.dx * e2y - r.dy * e2x;
  const V a = e1x * hx + e1y * hy + e1z * hz;
  out.mask = active & (abs(a) >= V::broadcast(1e-6f));
  if (!any(out.mask)) return out;
  const V f = V::broadcast(1.0f) / a;
  // u
  const V sx = r.ox - v0x, sy = r.oy - v0y, sz = r.oz - v0z;
  out.u = f * (sx * hx + sy * hy + sz * hz);
  out.mask = out.mask & (out.u >= V::broadcast(0.0f)) & (out.u <= V::broadcast(1.0f));
  if (!any(out.mask)) return out;
  // v
  const V qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
  out.v = f * (r.dx * qx + r.dy * qy + r.dz * qz);
  out.mask = out.mask & (out.v >= V::broadcast(0.0f)) & (out.u + out.v <= V::broadcast(1.0f));
  if (!any(out.mask)) return out;
  // depth test
  out.t = f * (e2x * qx + e2y * qy + e2z * qz);
  out.mask = out.mask & (out.t > V::broadcast(1e-6f)) & (out.t >= r.tmin) & (out.t < tlimit);
  return out;
}

// Möller–Trumbore without an absolute epsilon (intersector `mt` for vfloat, `mt64` for vdouble).
template <class V>
RAYVEC_INLINE LaneHits<V> test_mt(const TriangleArrays& T, uint32_t i, const RayLanes<V>& r,
                                  typename V::Mask active, V tlimit) {
  using S = typename V::Scalar;
  LaneHits<V> out;
  const uint32_t k = slot_offset(i);  // the step's lanes in each row (blocked rows)
  const V v0x = V::load(T.v0x + k), v0y = V::load(T.v0y + k), v0z = V::load(T.v0z + k);
  // edges from the exact vertices (in double for vdouble)
  const V e1x = V::load(T.v1x + k) - v0x, e1y = V::load(T.v1y + k) - v0y, e1z = V::load(T.v1z + k) - v0z;
  const V e2x = V::load(T.v2x + k) - v0x, e2y = V::load(T.v2y + k) - v0y, e2z = V::load(T.v2z + k) - v0z;
  // h = d × e2, det = e1 · h
  const V hx = fmsub(r.dy, e2z, r.dz * e2y);
  const V hy = fmsub(r.dz, e2x, r.dx * e2z);
  const V hz = fmsub(r.dx, e2y, r.dy * e2x);
  const V det = fmadd(e1x, hx, fmadd(e1y, hy, e1z * hz));
  // u·det = s · h, v·det = d · (s × e1)
  const V sx = r.ox - v0x, sy = r.oy - v0y, sz = r.oz - v0z;
  const V qx = fmsub(sy, e1z, sz * e1y);
  const V qy = fmsub(sz, e1x, sx * e1z);
  const V qz = fmsub(sx, e1y, sy * e1x);
  const V sign = sign_bit(det), adet = abs(det);
  const V un = xor_bits(fmadd(sx, hx, fmadd(sy, hy, sz * hz)), sign);
  const V vn = xor_bits(fmadd(r.dx, qx, fmadd(r.dy, qy, r.dz * qz)), sign);
  // edge tests (closed), det != 0; ordered compares reject NaN
  const V zero = V::broadcast(S(0));
  out.mask = active & (un >= zero) & (vn >= zero) & (un + vn <= adet) & (adet > zero);
  if (!any(out.mask)) return out;
  // depth test
  const V tn = xor_bits(fmadd(e2x, qx, fmadd(e2y, qy, e2z * qz)), sign);
  out.t = tn / adet;
  out.mask = out.mask & (out.t >= r.tmin) & (out.t < tlimit);
  if (any(out.mask)) {
    out.u = un / adet;
    out.v = vn / adet;
  }
  return out;
}

template <class V, Intersector I>
RAYVEC_INLINE LaneHits<V> test_lanes(const TriangleArrays& T, uint32_t i, const RayLanes<V>& r,
                                     typename V::Mask active, V tlimit) {
  if constexpr (I == Intersector::paper)
    return test_paper<V>(T, i, r, active, tlimit);
  else
    return test_mt<V>(T, i, r, active, tlimit);
}

template <class V, Intersector I>
void closest_impl(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  using S = typename V::Scalar;
  if (!finite_ray(ray)) return;
  constexpr int W = V::W;
  const RayLanes<V> r = broadcast_ray<V>(ray);
  const float limit = ray.tmax < hit.t ? ray.tmax : hit.t;
  const S initial = next_up(S(limit));  // lanes still at `initial` have no hit
  V best_t = V::broadcast(initial);
  V best_u = V::broadcast(S(0)), best_v = best_u, best_idx = best_u;
  bool found = false;
  for (uint32_t i = first_step(begin, W); i < end; i += W) {
    const LaneHits<V> h = test_lanes<V, I>(T, i, r, step_lanes<V>(i, begin, end), best_t);
    if (any(h.mask)) {  // blend nearest t, u, v and triangle index
      best_t = select(h.mask, best_t, h.t);
      best_u = select(h.mask, best_u, h.u);
      best_v = select(h.mask, best_v, h.v);
      best_idx = select(h.mask, best_idx, V::index_bits(i));
      found = true;
    }
  }
  if (!found) return;
  // final lane reduction: nearest t, then lowest id
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

template <class V, Intersector I>
bool occluded_impl(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray,
                   const HitFilter* filter) {
  using S = typename V::Scalar;
  if (!finite_ray(ray)) return false;
  const RayLanes<V> r = broadcast_ray<V>(ray);
  const V tlimit = V::broadcast(next_up(S(ray.tmax)));
  for (uint32_t i = first_step(begin, V::W); i < end; i += V::W) {
    const typename V::Mask m = test_lanes<V, I>(T, i, r, step_lanes<V>(i, begin, end), tlimit).mask;
    if (!any(m)) continue;
    if (!filter) return true;
    for (unsigned lanes = bits(m); lanes != 0; lanes &= lanes - 1)
      if (!filter->ignore(filter->context, T.id[slot_offset(i + unsigned(__builtin_ctz(lanes)))]))
        return true;
  }
  return false;
}
