// The ray–box slab test of the wide BVH, written once over a lane type L and compiled per ISA:
// box_lanes_<isa>.h defines its lane types (one register of L::W floats and the few operations
// below, each one intrinsic) and includes this file inside namespace rayvec::<isa>. No intrinsics
// here. The arithmetic and its robustness argument are documented in bvh/single_ray_traversal.inl; the
// operand order of every max/min is part of it (L::max(a, b) returns b when a is NaN).
//
// L provides: T, W, set1(float), load(const float*) (aligned), storeu(float*, T), sub, mul, max,
// min, fmadd(a, b, c) = a·b + c, fnmadd(a, b, c) = c − a·b, fmsub(a, b, c) = a·b − c, abs,
// le_bits(a, b) (bit k: a[k] <= b[k], ordered).

// Per-ray constants: origin, 1/d and, per axis, the bounds rows of the near and far planes
// (0..2 lo, 3..5 hi).
template <class L>
struct BoxRay {
  typename L::T ox, oy, oz, rx, ry, rz;
  int nx, ny, nz, fx, fy, fz;
};

// For rays with tmin >= 0: the reciprocals of the near and far planes, already scaled by (1 ∓ eps).
template <class L>
struct BoxForwardRay {
  typename L::T ox, oy, oz, nrx, nry, nrz, frx, fry, frz;
  int nx, ny, nz, fx, fy, fz;
};

// The hull of a packet of rays that all have tmin >= 0 and the same direction signs, as scalars
// (PacketForward<L, true>::hull): per axis the smallest and largest near- and far-plane
// reciprocals 1/d·(1 ∓ eps) over the lanes, the largest near-plane offset kn and the smallest
// far-plane offset kf (k = o·r' rounded outward), the bounds rows of the near and far planes, and
// the smallest tmin. packet_traversal.inl says why a box it misses is missed by every lane.
struct PacketHull {
  float nr_lo[3], nr_hi[3], kn_hi[3], fr_lo[3], fr_hi[3], kf_lo[3];
  float tmin;
  int near[3], far[3];
};

// PacketHull in lanes: each value broadcast.
template <class L>
struct BoxHull {
  typename L::T nr_lo[3], nr_hi[3], kn_hi[3], fr_lo[3], fr_hi[3], kf_lo[3], tmin;
  int near[3], far[3];
};

template <class L>
struct BoxPrepare {
  using RayData = BoxRay<L>;
  using ForwardRay = BoxForwardRay<L>;

  static RAYVEC_INLINE int far_row(int near) { return near < 3 ? near + 3 : near - 3; }

  static RAYVEC_INLINE ForwardRay prepare_forward(const float o[3], const float rdir[3], const int near[3],
                                                  float eps) {
    const float dn = 1.0f - eps, up = 1.0f + eps;
    return {L::set1(o[0]), L::set1(o[1]), L::set1(o[2]),
            L::set1(rdir[0] * dn), L::set1(rdir[1] * dn), L::set1(rdir[2] * dn),
            L::set1(rdir[0] * up), L::set1(rdir[1] * up), L::set1(rdir[2] * up),
            near[0], near[1], near[2], far_row(near[0]), far_row(near[1]), far_row(near[2])};
  }

  static RAYVEC_INLINE BoxHull<L> prepare_hull(const PacketHull& h) {
    BoxHull<L> b;
    for (int a = 0; a < 3; ++a) {
      b.nr_lo[a] = L::set1(h.nr_lo[a]);
      b.nr_hi[a] = L::set1(h.nr_hi[a]);
      b.kn_hi[a] = L::set1(h.kn_hi[a]);
      b.fr_lo[a] = L::set1(h.fr_lo[a]);
      b.fr_hi[a] = L::set1(h.fr_hi[a]);
      b.kf_lo[a] = L::set1(h.kf_lo[a]);
      b.near[a] = h.near[a];
      b.far[a] = h.far[a];
    }
    b.tmin = L::set1(h.tmin);
    return b;
  }

  static RAYVEC_INLINE RayData prepare(const float o[3], const float rdir[3], const int near[3]) {
    return {L::set1(o[0]), L::set1(o[1]), L::set1(o[2]),
            L::set1(rdir[0]), L::set1(rdir[1]), L::set1(rdir[2]),
            near[0], near[1], near[2], far_row(near[0]), far_row(near[1]), far_row(near[2])};
  }
};

// L::W children whose bounds rows start at b and lie Stride floats apart.
template <class L, int Stride>
struct BoxRows {
  // As hits() for a ray with tmin >= 0, the widening done by the scaled reciprocals (see
  // single_ray_traversal.inl): three fewer dependent operations a node.
  static RAYVEC_INLINE unsigned hits_forward(const float* b, const BoxForwardRay<L>& r, float tmin,
                                             float tmax, float* dist) {
    using T = typename L::T;
    const T tnx = L::mul(L::sub(L::load(b + long(r.nx) * Stride), r.ox), r.nrx);
    const T tny = L::mul(L::sub(L::load(b + long(r.ny) * Stride), r.oy), r.nry);
    const T tnz = L::mul(L::sub(L::load(b + long(r.nz) * Stride), r.oz), r.nrz);
    const T tfx = L::mul(L::sub(L::load(b + long(r.fx) * Stride), r.ox), r.frx);
    const T tfy = L::mul(L::sub(L::load(b + long(r.fy) * Stride), r.oy), r.fry);
    const T tfz = L::mul(L::sub(L::load(b + long(r.fz) * Stride), r.oz), r.frz);
    // the NaN slab (0·inf) is the first operand of each max/min, so it is skipped
    const T lo = L::max(tnz, L::max(tny, L::max(tnx, L::set1(tmin))));
    const T hi = L::min(tfz, L::min(tfy, L::min(tfx, L::set1(tmax))));
    L::storeu(dist, lo);
    return L::le_bits(lo, hi);
  }

  // Bit k clear when no lane of the packet whose hull is h (tmax: the largest tmax over its lanes)
  // enters child k's box under PacketForward<L, true>::hits. Per slab, the lower bound of the
  // lanes' entry distances b·r' − k: b·r' is linear in r', so its smallest value over
  // [nr_lo, nr_hi] is at one end, and k is at most kn_hi; the FMA rounds once and rounding is
  // monotonic, so fl(b·nr_x − kn_hi) for the smaller end is at most every lane's computed
  // distance. Exits mirror it. No NaN: the forward test's guard keeps every r' finite and nonzero.
  static RAYVEC_INLINE unsigned hits_hull(const float* b, const BoxHull<L>& h, typename L::T tmax) {
    using T = typename L::T;
    T lo = h.tmin, hi = tmax;
    for (int a = 0; a < 3; ++a) {
      const T bn = L::load(b + long(h.near[a]) * Stride), bf = L::load(b + long(h.far[a]) * Stride);
      lo = L::max(lo, L::min(L::fmsub(bn, h.nr_lo[a], h.kn_hi[a]), L::fmsub(bn, h.nr_hi[a], h.kn_hi[a])));
      hi = L::min(hi, L::max(L::fmsub(bf, h.fr_lo[a], h.kf_lo[a]), L::fmsub(bf, h.fr_hi[a], h.kf_lo[a])));
    }
    return L::le_bits(lo, hi);
  }

  // Bit k set when child k's box overlaps [tmin, tmax]; dist[k] = its entry distance.
  static RAYVEC_INLINE unsigned hits(const float* b, const BoxRay<L>& r, float tmin, float tmax,
                                     float eps, float* dist) {
    using T = typename L::T;
    const T tnx = L::mul(L::sub(L::load(b + long(r.nx) * Stride), r.ox), r.rx);
    const T tny = L::mul(L::sub(L::load(b + long(r.ny) * Stride), r.oy), r.ry);
    const T tnz = L::mul(L::sub(L::load(b + long(r.nz) * Stride), r.oz), r.rz);
    const T tfx = L::mul(L::sub(L::load(b + long(r.fx) * Stride), r.ox), r.rx);
    const T tfy = L::mul(L::sub(L::load(b + long(r.fy) * Stride), r.oy), r.ry);
    const T tfz = L::mul(L::sub(L::load(b + long(r.fz) * Stride), r.oz), r.rz);
    // max/min return the second operand when the first is NaN (0·inf: origin on a plane of an
    // axis the ray is parallel to), so such a slab is skipped
    T tn = L::max(tnx, L::set1(-__builtin_inff()));
    tn = L::max(tny, tn);
    tn = L::max(tnz, tn);
    T tf = L::min(tfx, L::set1(__builtin_inff()));
    tf = L::min(tfy, tf);
    tf = L::min(tfz, tf);
    // widen by |t|·eps; an infinite end becomes NaN, which misses below (the box is unreachable)
    const T e = L::set1(eps);
    tn = L::fnmadd(L::abs(tn), e, tn);
    tf = L::fmadd(L::abs(tf), e, tf);
    const T lo = L::max(L::set1(tmin), tn);  // a NaN second operand stays NaN
    const T hi = L::min(L::set1(tmax), tf);
    L::storeu(dist, lo);
    return L::le_bits(lo, hi);
  }
};

// A WideNode<L::W>: one register per bounds row.
template <class L>
struct BoxLanesOne : BoxPrepare<L> {
  static constexpr int N = L::W;
  static RAYVEC_INLINE unsigned hits_forward(const float (*b)[N], const BoxForwardRay<L>& r, float tmin,
                                             float tmax, float* dist) {
    return BoxRows<L, N>::hits_forward(b[0], r, tmin, tmax, dist);
  }
  static RAYVEC_INLINE unsigned hits(const float (*b)[N], const BoxRay<L>& r, float tmin, float tmax,
                                     float eps, float* dist) {
    return BoxRows<L, N>::hits(b[0], r, tmin, tmax, eps, dist);
  }
  static RAYVEC_INLINE unsigned hits_hull(const float (*b)[N], const BoxHull<L>& h, float tmax) {
    return BoxRows<L, N>::hits_hull(b[0], h, L::set1(tmax));
  }
};

// A WideNode<2·L::W>: two registers per bounds row (children 0..W−1, then W..2W−1).
template <class L>
struct BoxLanesTwo : BoxPrepare<L> {
  static constexpr int N = 2 * L::W;
  static RAYVEC_INLINE unsigned hits_forward(const float (*b)[N], const BoxForwardRay<L>& r, float tmin,
                                             float tmax, float* dist) {
    return BoxRows<L, N>::hits_forward(b[0], r, tmin, tmax, dist) |
           BoxRows<L, N>::hits_forward(b[0] + L::W, r, tmin, tmax, dist + L::W) << L::W;
  }
  static RAYVEC_INLINE unsigned hits(const float (*b)[N], const BoxRay<L>& r, float tmin, float tmax,
                                     float eps, float* dist) {
    return BoxRows<L, N>::hits(b[0], r, tmin, tmax, eps, dist) |
           BoxRows<L, N>::hits(b[0] + L::W, r, tmin, tmax, eps, dist + L::W) << L::W;
  }
  static RAYVEC_INLINE unsigned hits_hull(const float (*b)[N], const BoxHull<L>& h, float tmax) {
    const typename L::T t = L::set1(tmax);
    return BoxRows<L, N>::hits_hull(b[0], h, t) | BoxRows<L, N>::hits_hull(b[0] + L::W, h, t) << L::W;
  }
};
