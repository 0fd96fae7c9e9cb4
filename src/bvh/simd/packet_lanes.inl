// The packet box tests of bvh/packet_traversal.inl, written once over a lane type L (one register of
// P = L::W rays, one per lane) and compiled per ISA: packet_lanes_<isa>.h includes this inside
// namespace rayvec::<isa> and adds what differs per ISA (the AoS → SoA transpose of the rays, the
// root box, a lane reduction). No intrinsics here. The arithmetic is BoxLanes' (box_lanes.inl),
// transposed: one child box against every lane; the robustness arguments are in
// bvh/single_ray_traversal.inl and bvh/packet_traversal.inl.
//
// L provides, beyond box_lanes.inl's operations: loadu, fmsub(a, b, c) = a·b − c, Signs (a lane
// mask type), signs_of(r) (the lanes whose r has its sign bit set), signs_from_bits(unsigned),
// blend(Signs m, a, b) (b in the lanes of m, a elsewhere), max_lanes(T, unsigned lanes) and
// min_lanes(T, unsigned lanes) (the largest and smallest lane of `lanes`, nonzero).

// The general test (any tmin): the widening per child, as BoxLanes does it. Each lane picks its
// near plane by the sign of its own direction, so a lane's answer equals the single-ray test's.
// Self: the ISA's packet type deriving from this (load returns it).
template <class L, class Self>
struct PacketLanesBase {
  using T = typename L::T;
  static constexpr int P = L::W;
  T ox, oy, oz, rx, ry, rz, tmin, tmax;
  typename L::Signs nx, ny, nz;  // lanes whose direction has its sign bit set

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax.
  static RAYVEC_INLINE Self load(const float* const soa[8]) {
    Self k;
    k.ox = L::loadu(soa[0]); k.oy = L::loadu(soa[1]); k.oz = L::loadu(soa[2]);
    k.rx = L::loadu(soa[3]); k.ry = L::loadu(soa[4]); k.rz = L::loadu(soa[5]);
    k.tmin = L::loadu(soa[6]); k.tmax = L::loadu(soa[7]);
    k.nx = L::signs_of(k.rx); k.ny = L::signs_of(k.ry); k.nz = L::signs_of(k.rz);
    return k;
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = L::loadu(t); }
  // The largest current tmax over `lanes` (nonzero).
  RAYVEC_INLINE float max_tmax(unsigned lanes) const { return L::max_lanes(tmax, lanes); }

  // Lanes (within `active`) whose ray overlaps child k's box of a node with N children; tn receives
  // each lane's entry distance.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float eps,
                              float* tn_out) const {
    const T lx = L::set1(b[0][k]), ly = L::set1(b[1][k]), lz = L::set1(b[2][k]);
    const T hx = L::set1(b[3][k]), hy = L::set1(b[4][k]), hz = L::set1(b[5][k]);
    const T tnx = L::mul(L::sub(L::blend(nx, lx, hx), ox), rx);
    const T tny = L::mul(L::sub(L::blend(ny, ly, hy), oy), ry);
    const T tnz = L::mul(L::sub(L::blend(nz, lz, hz), oz), rz);
    const T tfx = L::mul(L::sub(L::blend(nx, hx, lx), ox), rx);
    const T tfy = L::mul(L::sub(L::blend(ny, hy, ly), oy), ry);
    const T tfz = L::mul(L::sub(L::blend(nz, hz, lz), oz), rz);
    T tn = L::max(tnx, L::set1(-__builtin_inff()));
    tn = L::max(tny, tn);
    tn = L::max(tnz, tn);
    T tf = L::min(tfx, L::set1(__builtin_inff()));
    tf = L::min(tfy, tf);
    tf = L::min(tfz, tf);
    const T e = L::set1(eps);
    tn = L::fnmadd(L::abs(tn), e, tn);
    tf = L::fmadd(L::abs(tf), e, tf);
    const T lo = L::max(tmin, tn);
    const T hi = L::min(tmax, tf);
    L::storeu(tn_out, lo);
    return L::le_bits(lo, hi) & active;
  }
};

// The test for a packet with every tmin >= 0 whose slabs cannot overflow (the guard and the
// robustness argument are in bvh/packet_traversal.inl): each slab distance in one FMA, b·r' − k, with
// r' = 1/d·(1 ∓ eps) for the near and far planes and k = o·r' rounded outward, so neither widening
// nor a subtraction of o is left per child (Ize 2013 folds the widening into the reciprocals the
// same way). Uniform: every lane has the same direction signs, so the near and far planes are the
// same bounds rows for all lanes and no blend is needed.
template <class L, bool Uniform>
struct PacketForward {
  using T = typename L::T;
  T nrx, nry, nrz, frx, fry, frz, knx, kny, knz, kfx, kfy, kfz, tmin, tmax;
  typename L::Signs sx, sy, sz;  // lanes whose direction is negative: near plane hi, far plane lo
  int nx, ny, nz, fx, fy, fz;    // Uniform: the bounds rows of the near and far planes

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax; neg[a]: the lanes with
  // rdir[a] < 0 (Uniform: none or all of the active lanes).
  static RAYVEC_INLINE PacketForward load(const float* const soa[8], const unsigned neg[3], float eps) {
    PacketForward k;
    const T dn = L::set1(1.0f - eps), up = L::set1(1.0f + eps);
    T* const nr[3] = {&k.nrx, &k.nry, &k.nrz};
    T* const fr[3] = {&k.frx, &k.fry, &k.frz};
    T* const kn[3] = {&k.knx, &k.kny, &k.knz};
    T* const kf[3] = {&k.kfx, &k.kfy, &k.kfz};
    for (int a = 0; a < 3; ++a) {
      const T o = L::loadu(soa[a]), r = L::loadu(soa[3 + a]);
      *nr[a] = L::mul(r, dn);
      *fr[a] = L::mul(r, up);
      *kn[a] = outward(L::mul(o, *nr[a]), L::set1(1.0f));
      *kf[a] = outward(L::mul(o, *fr[a]), L::set1(-1.0f));
    }
    k.tmin = L::loadu(soa[6]);
    k.tmax = L::loadu(soa[7]);
    k.sx = L::signs_from_bits(neg[0]); k.sy = L::signs_from_bits(neg[1]); k.sz = L::signs_from_bits(neg[2]);
    k.nx = neg[0] ? 3 : 0; k.ny = neg[1] ? 4 : 1; k.nz = neg[2] ? 5 : 2;
    k.fx = neg[0] ? 0 : 3; k.fy = neg[1] ? 1 : 4; k.fz = neg[2] ? 2 : 5;
    return k;
  }
  // p moved away from zero-crossing toward `dir` (+1 up, −1 down) by more than its rounding
  // error: max(|p|·2^-22, 2^-149) is at least two ulps of a normal p and one subnormal step.
  static RAYVEC_INLINE T outward(T p, T dir) {
    const T step = L::max(L::mul(L::abs(p), L::set1(0x1p-22f)), L::set1(0x1p-149f));
    return L::fmadd(step, dir, p);
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = L::loadu(t); }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const { return L::max_lanes(tmax, lanes); }

  // The hull of the lanes `lanes` (box_lanes.inl's PacketHull); Uniform only, where every lane has
  // the same near and far planes.
  RAYVEC_INLINE PacketHull hull(unsigned lanes) const {
    static_assert(Uniform, "a hull needs the same near and far planes in every lane");
    const T nr[3] = {nrx, nry, nrz}, fr[3] = {frx, fry, frz};
    const T kn[3] = {knx, kny, knz}, kf[3] = {kfx, kfy, kfz};
    const int near[3] = {nx, ny, nz}, far[3] = {fx, fy, fz};
    PacketHull h;
    for (int a = 0; a < 3; ++a) {
      h.nr_lo[a] = L::min_lanes(nr[a], lanes);
      h.nr_hi[a] = L::max_lanes(nr[a], lanes);
      h.kn_hi[a] = L::max_lanes(kn[a], lanes);
      h.fr_lo[a] = L::min_lanes(fr[a], lanes);
      h.fr_hi[a] = L::max_lanes(fr[a], lanes);
      h.kf_lo[a] = L::min_lanes(kf[a], lanes);
      h.near[a] = near[a];
      h.far[a] = far[a];
    }
    h.tmin = L::min_lanes(tmin, lanes);
    return h;
  }

  // As PacketLanesBase::hits.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float* tn_out) const {
    T bnx, bny, bnz, bfx, bfy, bfz;
    if constexpr (Uniform) {
      bnx = L::set1(b[nx][k]); bny = L::set1(b[ny][k]); bnz = L::set1(b[nz][k]);
      bfx = L::set1(b[fx][k]); bfy = L::set1(b[fy][k]); bfz = L::set1(b[fz][k]);
    } else {
      const T lx = L::set1(b[0][k]), ly = L::set1(b[1][k]), lz = L::set1(b[2][k]);
      const T hx = L::set1(b[3][k]), hy = L::set1(b[4][k]), hz = L::set1(b[5][k]);
      bnx = L::blend(sx, lx, hx); bny = L::blend(sy, ly, hy); bnz = L::blend(sz, lz, hz);
      bfx = L::blend(sx, hx, lx); bfy = L::blend(sy, hy, ly); bfz = L::blend(sz, hz, lz);
    }
    const T tnx = L::fmsub(bnx, nrx, knx), tny = L::fmsub(bny, nry, kny), tnz = L::fmsub(bnz, nrz, knz);
    const T tfx = L::fmsub(bfx, frx, kfx), tfy = L::fmsub(bfy, fry, kfy), tfz = L::fmsub(bfz, frz, kfz);
    const T lo = L::max(L::max(tnx, tmin), L::max(tny, tnz));
    const T hi = L::min(L::min(tfx, tmax), L::min(tfy, tfz));
    L::storeu(tn_out, lo);
    return L::le_bits(lo, hi) & active;
  }
};
