// The packet box tests of bvh/packet_traversal.inl, written once over a lane type V of the SIMD
// vocabulary (one vfloat of P = V::W rays, one per lane) and compiled per ISA: packet_lanes_<isa>.h
// includes this inside namespace rayvec::<isa> and adds what differs per ISA (the AoS → SoA
// transpose of the rays). No intrinsics here. The arithmetic is BoxLanes' (box_lanes.inl),
// transposed: one child box against every lane; the robustness arguments are in
// bvh/single_ray_traversal.inl and bvh/packet_traversal.inl.
//
// V provides, beyond box_lanes.inl's operations: load (unaligned), Mask, sign_mask(r) (the lanes
// whose r has its sign bit set), mask_from_bits(V, unsigned), select(m, a, b) (b in the lanes of m,
// a elsewhere), hmax_lanes(v, lanes) and hmin_lanes(v, lanes) (the largest and smallest lane of
// `lanes`, nonzero).

// The general test (any tmin): the widening per child, as BoxLanes does it. Each lane picks its
// near plane by the sign of its own direction, so a lane's answer equals the single-ray test's.
// Self: the ISA's packet type deriving from this (load returns it).
template <class V, class Self>
struct PacketLanesBase {
  static constexpr int P = V::W;
  V ox, oy, oz, rx, ry, rz, tmin, tmax;
  typename V::Mask nx, ny, nz;  // lanes whose direction has its sign bit set

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax.
  static RAYVEC_INLINE Self load(const float* const soa[8]) {
    Self k;
    k.ox = V::load(soa[0]);
    k.oy = V::load(soa[1]);
    k.oz = V::load(soa[2]);
    k.rx = V::load(soa[3]);
    k.ry = V::load(soa[4]);
    k.rz = V::load(soa[5]);
    k.tmin = V::load(soa[6]);
    k.tmax = V::load(soa[7]);
    k.nx = sign_mask(k.rx);
    k.ny = sign_mask(k.ry);
    k.nz = sign_mask(k.rz);
    return k;
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = V::load(t); }
  // The largest current tmax over `lanes` (nonzero).
  RAYVEC_INLINE float max_tmax(unsigned lanes) const { return hmax_lanes(tmax, lanes); }

  // Lanes (within `active`) whose ray overlaps child k's box of a node with N children; tn receives
  // each lane's entry distance.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float eps, float* tn_out) const {
    const V lx = V::broadcast(b[0][k]), ly = V::broadcast(b[1][k]), lz = V::broadcast(b[2][k]);
    const V hx = V::broadcast(b[3][k]), hy = V::broadcast(b[4][k]), hz = V::broadcast(b[5][k]);
    const V tnx = (select(nx, lx, hx) - ox) * rx;
    const V tny = (select(ny, ly, hy) - oy) * ry;
    const V tnz = (select(nz, lz, hz) - oz) * rz;
    const V tfx = (select(nx, hx, lx) - ox) * rx;
    const V tfy = (select(ny, hy, ly) - oy) * ry;
    const V tfz = (select(nz, hz, lz) - oz) * rz;
    V tn = vmax(tnx, V::broadcast(-__builtin_inff()));
    tn = vmax(tny, tn);
    tn = vmax(tnz, tn);
    V tf = vmin(tfx, V::broadcast(__builtin_inff()));
    tf = vmin(tfy, tf);
    tf = vmin(tfz, tf);
    const V e = V::broadcast(eps);
    tn = fnmadd(abs(tn), e, tn);
    tf = fmadd(abs(tf), e, tf);
    const V lo = vmax(tmin, tn);
    const V hi = vmin(tmax, tf);
    lo.store(tn_out);
    return bits(lo <= hi) & active;
  }
};

// The test for a packet with every tmin >= 0 whose slabs cannot overflow (the guard and the
// robustness argument are in bvh/packet_traversal.inl): each slab distance in one FMA, b·r' − k, with
// r' = 1/d·(1 ∓ eps) for the near and far planes and k = o·r' rounded outward, so neither widening
// nor a subtraction of o is left per child (Ize 2013 folds the widening into the reciprocals the
// same way). Uniform: every lane has the same direction signs, so the near and far planes are the
// same bounds rows for all lanes and no blend is needed.
template <class V, bool Uniform>
struct PacketForward {
  V nrx, nry, nrz, frx, fry, frz, knx, kny, knz, kfx, kfy, kfz, tmin, tmax;
  typename V::Mask sx, sy, sz;  // lanes whose direction is negative: near plane hi, far plane lo
  int nx, ny, nz, fx, fy, fz;   // Uniform: the bounds rows of the near and far planes
  float near_scale, far_scale;  // 1 − eps and 1 + eps: nr = r · near_scale, fr = r · far_scale

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax; neg[a]: the lanes with
  // rdir[a] < 0 (Uniform: none or all of the active lanes).
  static RAYVEC_INLINE PacketForward load(const float* const soa[8], const unsigned neg[3], float eps) {
    PacketForward k;
    k.near_scale = 1.0f - eps;
    k.far_scale = 1.0f + eps;
    const V dn = V::broadcast(k.near_scale), up = V::broadcast(k.far_scale);
    V* const nr[3] = {&k.nrx, &k.nry, &k.nrz};
    V* const fr[3] = {&k.frx, &k.fry, &k.frz};
    V* const kn[3] = {&k.knx, &k.kny, &k.knz};
    V* const kf[3] = {&k.kfx, &k.kfy, &k.kfz};
    for (int a = 0; a < 3; ++a) {
      const V o = V::load(soa[a]), r = V::load(soa[3 + a]);
      *nr[a] = r * dn;
      *fr[a] = r * up;
      *kn[a] = outward(o * *nr[a], V::broadcast(1.0f));
      *kf[a] = outward(o * *fr[a], V::broadcast(-1.0f));
    }
    k.tmin = V::load(soa[6]);
    k.tmax = V::load(soa[7]);
    k.sx = mask_from_bits(V{}, neg[0]);
    k.sy = mask_from_bits(V{}, neg[1]);
    k.sz = mask_from_bits(V{}, neg[2]);
    k.nx = neg[0] ? 3 : 0;
    k.ny = neg[1] ? 4 : 1;
    k.nz = neg[2] ? 5 : 2;
    k.fx = neg[0] ? 0 : 3;
    k.fy = neg[1] ? 1 : 4;
    k.fz = neg[2] ? 2 : 5;
    return k;
  }
  // p moved away from zero-crossing toward `dir` (+1 up, −1 down) by more than its rounding
  // error: max(|p|·2^-22, 2^-126) is at least two ulps of a normal p and more than the error of a
  // subnormal one. The floor is the smallest normal float, not one subnormal step: an origin
  // coordinate of 0 (a camera on an axis plane) gives p = 0, and a subnormal offset in every box
  // test's FMA took Intel's microcode assist, several times the traversal's time
  // (benchmarks.md#decision-normal-box-offsets).
  static RAYVEC_INLINE V outward(V p, V dir) {
    const V step = vmax(abs(p) * V::broadcast(0x1p-22f), V::broadcast(0x1p-126f));
    return fmadd(step, dir, p);
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = V::load(t); }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const { return hmax_lanes(tmax, lanes); }

  // The hull of the lanes `lanes` (box_lanes.inl's PacketHull), r[a] the lanes' 1/d; Uniform only,
  // where every lane has the same near and far planes. *tmax_hi: the largest tmax of those lanes.
  // nr and fr are r times constants above zero, so their extremes are those of r times the
  // constants — a product with a positive constant is monotonic under rounding: the same bits as
  // reducing nr and fr themselves, in six reductions fewer (benchmarks.md#decision-scalar-hull).
  RAYVEC_INLINE PacketHull hull(const V r[3], unsigned lanes, float* tmax_hi) const {
    static_assert(Uniform, "a hull needs the same near and far planes in every lane");
    const V kn[3] = {knx, kny, knz}, kf[3] = {kfx, kfy, kfz};
    const int near[3] = {nx, ny, nz}, far[3] = {fx, fy, fz};
    PacketHull h;
    for (int a = 0; a < 3; ++a) {
      const float r_lo = hmin_lanes(r[a], lanes), r_hi = hmax_lanes(r[a], lanes);
      h.nr_lo[a] = r_lo * near_scale;
      h.nr_hi[a] = r_hi * near_scale;
      h.fr_lo[a] = r_lo * far_scale;
      h.fr_hi[a] = r_hi * far_scale;
      h.kn_hi[a] = hmax_lanes(kn[a], lanes);
      h.kf_lo[a] = hmin_lanes(kf[a], lanes);
      h.near[a] = near[a];
      h.far[a] = far[a];
    }
    h.tmin = hmin_lanes(tmin, lanes);
    *tmax_hi = hmax_lanes(tmax, lanes);
    return h;
  }

  // As PacketLanesBase::hits.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float* tn_out) const {
    V bnx, bny, bnz, bfx, bfy, bfz;
    if constexpr (Uniform) {
      bnx = V::broadcast(b[nx][k]);
      bny = V::broadcast(b[ny][k]);
      bnz = V::broadcast(b[nz][k]);
      bfx = V::broadcast(b[fx][k]);
      bfy = V::broadcast(b[fy][k]);
      bfz = V::broadcast(b[fz][k]);
    } else {
      const V lx = V::broadcast(b[0][k]), ly = V::broadcast(b[1][k]), lz = V::broadcast(b[2][k]);
      const V hx = V::broadcast(b[3][k]), hy = V::broadcast(b[4][k]), hz = V::broadcast(b[5][k]);
      bnx = select(sx, lx, hx);
      bny = select(sy, ly, hy);
      bnz = select(sz, lz, hz);
      bfx = select(sx, hx, lx);
      bfy = select(sy, hy, ly);
      bfz = select(sz, hz, lz);
    }
    const V tnx = fmsub(bnx, nrx, knx), tny = fmsub(bny, nry, kny), tnz = fmsub(bnz, nrz, knz);
    const V tfx = fmsub(bfx, frx, kfx), tfy = fmsub(bfy, fry, kfy), tfz = fmsub(bfz, frz, kfz);
    const V lo = vmax(vmax(tnx, tmin), vmax(tny, tnz));
    const V hi = vmin(vmin(tfx, tmax), vmin(tfy, tfz));
    lo.store(tn_out);
    return bits(lo <= hi) & active;
  }
};
