// The ray–box slab test of the wide BVH, written once over a lane type V of the SIMD vocabulary
// (src/simd/vfloat_<isa>.h: vfloat, and on AVX-512 also vfloat8 for 8-wide nodes) and compiled per
// ISA: box_lanes_<isa>.h includes this file inside namespace rayvec::<isa>, after that ISA's vfloat
// header. No intrinsics here. The arithmetic and its robustness argument are documented in
// bvh/single_ray_traversal.inl; the operand order of every vmax/vmin is part of it (vmax(a, b)
// returns b when a is NaN).
//
// V provides: W, broadcast, load_aligned, store, -, *, vmax, vmin, fmadd(a, b, c) = a·b + c,
// fnmadd(a, b, c) = c − a·b, fmsub(a, b, c) = a·b − c, abs, <= (ordered) and bits() of its mask.

// Per-ray constants: origin, 1/d and, per axis, the bounds rows of the near and far planes
// (0..2 lo, 3..5 hi).
template <class V>
struct BoxRay {
  V ox, oy, oz, rx, ry, rz;
  int nx, ny, nz, fx, fy, fz;
};

// For rays with tmin >= 0: the reciprocals of the near and far planes, already scaled by (1 ∓ eps).
template <class V>
struct BoxForwardRay {
  V ox, oy, oz, nrx, nry, nrz, frx, fry, frz;
  int nx, ny, nz, fx, fy, fz;
};

// The hull of a packet of rays that all have tmin >= 0 and the same direction signs, as scalars
// (PacketForward<V, true>::hull): per axis the smallest and largest near- and far-plane
// reciprocals 1/d·(1 ∓ eps) over the lanes, the largest near-plane offset kn and the smallest
// far-plane offset kf (k = o·r' rounded outward), the bounds rows of the near and far planes, and
// the smallest tmin. packet_traversal.inl says why a box it misses is missed by every lane.
struct PacketHull {
  float nr_lo[3], nr_hi[3], kn_hi[3], fr_lo[3], fr_hi[3], kf_lo[3];
  float tmin;
  int near[3], far[3];
};

template <class V>
struct BoxPrepare {
  using RayData = BoxRay<V>;
  using ForwardRay = BoxForwardRay<V>;

  static RAYVEC_INLINE int far_row(int near) { return near < 3 ? near + 3 : near - 3; }

  static RAYVEC_INLINE ForwardRay prepare_forward(const float o[3], const float rdir[3], const int near[3],
                                                  float eps) {
    const float dn = 1.0f - eps, up = 1.0f + eps;
    return {V::broadcast(o[0]),
            V::broadcast(o[1]),
            V::broadcast(o[2]),
            V::broadcast(rdir[0] * dn),
            V::broadcast(rdir[1] * dn),
            V::broadcast(rdir[2] * dn),
            V::broadcast(rdir[0] * up),
            V::broadcast(rdir[1] * up),
            V::broadcast(rdir[2] * up),
            near[0],
            near[1],
            near[2],
            far_row(near[0]),
            far_row(near[1]),
            far_row(near[2])};
  }

  static RAYVEC_INLINE RayData prepare(const float o[3], const float rdir[3], const int near[3]) {
    return {V::broadcast(o[0]),
            V::broadcast(o[1]),
            V::broadcast(o[2]),
            V::broadcast(rdir[0]),
            V::broadcast(rdir[1]),
            V::broadcast(rdir[2]),
            near[0],
            near[1],
            near[2],
            far_row(near[0]),
            far_row(near[1]),
            far_row(near[2])};
  }
};

// V::W children whose bounds rows start at b and lie Stride floats apart.
template <class V, int Stride>
struct BoxRows {
  // As hits() for a ray with tmin >= 0, the widening done by the scaled reciprocals (see
  // single_ray_traversal.inl): three fewer dependent operations a node.
  static RAYVEC_INLINE unsigned hits_forward(const float* b, const BoxForwardRay<V>& r, float tmin,
                                             float tmax, float* dist) {
    const V tnx = (V::load_aligned(b + long(r.nx) * Stride) - r.ox) * r.nrx;
    const V tny = (V::load_aligned(b + long(r.ny) * Stride) - r.oy) * r.nry;
    const V tnz = (V::load_aligned(b + long(r.nz) * Stride) - r.oz) * r.nrz;
    const V tfx = (V::load_aligned(b + long(r.fx) * Stride) - r.ox) * r.frx;
    const V tfy = (V::load_aligned(b + long(r.fy) * Stride) - r.oy) * r.fry;
    const V tfz = (V::load_aligned(b + long(r.fz) * Stride) - r.oz) * r.frz;
    // the NaN slab (0·inf) is the first operand of each max/min, so it is skipped
    const V lo = vmax(tnz, vmax(tny, vmax(tnx, V::broadcast(tmin))));
    const V hi = vmin(tfz, vmin(tfy, vmin(tfx, V::broadcast(tmax))));
    lo.store(dist);
    return bits(lo <= hi);
  }

  // Bit k clear when no lane of the packet whose hull is h (tmax: the largest tmax over its lanes)
  // enters child k's box under PacketForward<V, true>::hits. Per slab, the lower bound of the
  // lanes' entry distances b·r' − k: b·r' is linear in r', so its smallest value over
  // [nr_lo, nr_hi] is at one end, and k is at most kn_hi; the FMA rounds once and rounding is
  // monotonic, so fl(b·nr_x − kn_hi) for the smaller end is at most every lane's computed
  // distance. Exits mirror it. No NaN: the forward test's guard keeps every r' finite and nonzero.
  // The hull stays scalars, broadcast where used (a load either way, and folded into the FMAs'
  // operands on AVX-512): held as 19 registers it was stored and copied for every packet
  // (benchmarks.md#decision-scalar-hull).
  // tmin: h.tmin, or a smaller bound of the lanes' entries (packet_slot_cull.inl's 0).
  static RAYVEC_INLINE unsigned hits_hull(const float* b, const PacketHull& h, V tmin, V tmax) {
    V lo = tmin, hi = tmax;
    for (int a = 0; a < 3; ++a) {
      const V bn = V::load_aligned(b + long(h.near[a]) * Stride),
              bf = V::load_aligned(b + long(h.far[a]) * Stride);
      const V kn = V::broadcast(h.kn_hi[a]), kf = V::broadcast(h.kf_lo[a]);
      lo = vmax(lo, vmin(fmsub(bn, V::broadcast(h.nr_lo[a]), kn), fmsub(bn, V::broadcast(h.nr_hi[a]), kn)));
      hi = vmin(hi, vmax(fmsub(bf, V::broadcast(h.fr_lo[a]), kf), fmsub(bf, V::broadcast(h.fr_hi[a]), kf)));
    }
    return bits(lo <= hi);
  }

  // Bit k set when child k's box overlaps [tmin, tmax]; dist[k] = its entry distance.
  static RAYVEC_INLINE unsigned hits(const float* b, const BoxRay<V>& r, float tmin, float tmax, float eps,
                                     float* dist) {
    const V tnx = (V::load_aligned(b + long(r.nx) * Stride) - r.ox) * r.rx;
    const V tny = (V::load_aligned(b + long(r.ny) * Stride) - r.oy) * r.ry;
    const V tnz = (V::load_aligned(b + long(r.nz) * Stride) - r.oz) * r.rz;
    const V tfx = (V::load_aligned(b + long(r.fx) * Stride) - r.ox) * r.rx;
    const V tfy = (V::load_aligned(b + long(r.fy) * Stride) - r.oy) * r.ry;
    const V tfz = (V::load_aligned(b + long(r.fz) * Stride) - r.oz) * r.rz;
    // max/min return the second operand when the first is NaN (0·inf: origin on a plane of an
    // axis the ray is parallel to), so such a slab is skipped
    V tn = vmax(tnx, V::broadcast(-__builtin_inff()));
    tn = vmax(tny, tn);
    tn = vmax(tnz, tn);
    V tf = vmin(tfx, V::broadcast(__builtin_inff()));
    tf = vmin(tfy, tf);
    tf = vmin(tfz, tf);
    // widen by |t|·eps; an infinite end becomes NaN, which misses below (the box is unreachable)
    const V e = V::broadcast(eps);
    tn = fnmadd(abs(tn), e, tn);
    tf = fmadd(abs(tf), e, tf);
    const V lo = vmax(V::broadcast(tmin), tn);  // a NaN second operand stays NaN
    const V hi = vmin(V::broadcast(tmax), tf);
    lo.store(dist);
    return bits(lo <= hi);
  }
};

// A WideNode<N>: N / V::W registers per bounds row, the children k·W … k·W + W − 1 in register k
// (one register on AVX-512, two for AVX2's 16-wide nodes, one child at a time on the scalar ISA).
// The registers are tested by a fold over k, which compiles to straight-line code.
// (std::integer_sequence is a type only: no code is instantiated from std here.)
template <class V, int Children, class Registers = std::make_integer_sequence<int, Children / V::W>>
struct BoxLanes;
template <class V, int Children, int... K>
struct BoxLanes<V, Children, std::integer_sequence<int, K...>> : BoxPrepare<V> {
  static constexpr int N = Children;
  static_assert(N % V::W == 0, "a node holds whole registers of children");
  static RAYVEC_INLINE unsigned hits_forward(const float (*b)[N], const BoxForwardRay<V>& r, float tmin,
                                             float tmax, float* dist) {
    return (... |
            (BoxRows<V, N>::hits_forward(b[0] + K * V::W, r, tmin, tmax, dist + K * V::W) << (K * V::W)));
  }
  static RAYVEC_INLINE unsigned hits(const float (*b)[N], const BoxRay<V>& r, float tmin, float tmax,
                                     float eps, float* dist) {
    return (... | (BoxRows<V, N>::hits(b[0] + K * V::W, r, tmin, tmax, eps, dist + K * V::W) << (K * V::W)));
  }
  static RAYVEC_INLINE unsigned hits_hull(const float (*b)[N], const PacketHull& h, float tmin, float tmax) {
    const V t0 = V::broadcast(tmin), t1 = V::broadcast(tmax);
    return (... | (BoxRows<V, N>::hits_hull(b[0] + K * V::W, h, t0, t1) << (K * V::W)));
  }
};
