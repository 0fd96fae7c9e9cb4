// AVX-512 packet lanes for bvh/bvh_packet.inl: 16 rays, one per zmm lane, against one child box
// of a wide node at a time (PacketLanes16: any tmin, the widening per child as BoxLanes16 does it;
// PacketLanes16Forward: tmin >= 0, one FMA a slab), plus the packet's setup (the AoS → SoA
// transpose of its rays, the root box). One of the only files that include <immintrin.h>;
// included only by *_avx512.cpp units after box_lanes_avx512.h, in namespace rayvec::avx512.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "kernels/simd/box_lanes_avx512.h"

namespace rayvec::avx512 {

template <bool Uniform>
struct PacketLanes16Forward;

// A packet of 16 rays, one per lane, for packet traversal (bvh/bvh_packet.inl): the same slab
// arithmetic as BoxLanes16, transposed — one child box against every lane. Each lane picks
// its near plane by the sign of its own direction, so a lane's answer equals the single-ray test's.
struct PacketLanes16 {
  static constexpr int P = 16;
  template <bool Uniform>
  using Forward = PacketLanes16Forward<Uniform>;
  __m512 ox, oy, oz, rx, ry, rz, tmin, tmax;
  __mmask16 nx, ny, nz;  // lanes whose direction has its sign bit set

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax.
  static RAYVEC_INLINE PacketLanes16 load(const float* const soa[8]) {
    PacketLanes16 k;
    k.ox = _mm512_loadu_ps(soa[0]); k.oy = _mm512_loadu_ps(soa[1]); k.oz = _mm512_loadu_ps(soa[2]);
    k.rx = _mm512_loadu_ps(soa[3]); k.ry = _mm512_loadu_ps(soa[4]); k.rz = _mm512_loadu_ps(soa[5]);
    k.tmin = _mm512_loadu_ps(soa[6]); k.tmax = _mm512_loadu_ps(soa[7]);
    k.nx = _mm512_movepi32_mask(_mm512_castps_si512(k.rx));
    k.ny = _mm512_movepi32_mask(_mm512_castps_si512(k.ry));
    k.nz = _mm512_movepi32_mask(_mm512_castps_si512(k.rz));
    return k;
  }
  // Transposes 16 rays of 8 floats each (the Ray layout: o, d, tmin, tmax; ray k at rays + 8k) into
  // rows[f][k], reading only the rays of `lanes` (the others' rows are 0). Returns the lanes of
  // `lanes` whose ray is traceable: finite origin and direction, tmin and tmax not NaN.
  // Two rays per load; three stages of two-register shuffles each trade one bit of the register
  // index (ray) for one bit of the lane index (field): unpacklo/hi (ray bit 0 for field bit 1),
  // shufps (ray bit 1 for field bit 0), vpermt2ps (ray bit 2 for field bit 2, putting lanes in ray
  // order) — 24 shuffles instead of 128 scalar loads and stores (and no store-forwarding stall).
  static RAYVEC_INLINE unsigned load_rays(const float* rays, unsigned lanes, float (*rows)[16]) {
    __m512 r[8], s[8];
    if (lanes == 0xffffu) {
      for (int j = 0; j < 8; ++j) r[j] = _mm512_loadu_ps(rays + 16 * j);
    } else {
      for (int j = 0; j < 8; ++j) {
        const unsigned two = (lanes >> (2 * j)) & 3u;
        const __mmask16 m = __mmask16((two & 1u ? 0x00ffu : 0u) | (two & 2u ? 0xff00u : 0u));
        r[j] = _mm512_maskz_loadu_ps(m, rays + 16 * j);
      }
    }
    for (int j = 0; j < 8; j += 2) {  // slot bit 0 becomes field bit 1
      // maskz forms: g++ 12's plain ones merge into _mm512_undefined_ps() and warn
      s[j] = _mm512_maskz_unpacklo_ps(__mmask16(0xffff), r[j], r[j + 1]);
      s[j + 1] = _mm512_maskz_unpackhi_ps(__mmask16(0xffff), r[j], r[j + 1]);
    }
    for (int j : {0, 1, 4, 5}) {  // slot bit 1 becomes field bit 0
      r[j] = _mm512_shuffle_ps(s[j], s[j + 2], 0x44);
      r[j + 2] = _mm512_shuffle_ps(s[j], s[j + 2], 0xee);
    }
    // slot bit 2 becomes field bit 2; lane (h, field bit 2, ray bits 1, 0) -> lane = ray
    const __m512i lo = _mm512_setr_epi32(0, 8, 1, 9, 2, 10, 3, 11, 16, 24, 17, 25, 18, 26, 19, 27);
    const __m512i hi = _mm512_add_epi32(lo, _mm512_set1_epi32(4));
    for (int j = 0; j < 4; ++j) {
      s[j] = _mm512_permutex2var_ps(r[j], lo, r[j + 4]);
      s[j + 4] = _mm512_permutex2var_ps(r[j], hi, r[j + 4]);
    }
    // slot (field bit 2, field bit 0, field bit 1)
    for (int f = 0; f < 8; ++f) _mm512_store_ps(rows[f], s[(f & 4) | ((f & 1) << 1) | ((f & 2) >> 1)]);
    // fpclass 0x99: QNaN, SNaN, +inf, -inf; 0x81: QNaN, SNaN
    unsigned bad = 0;
    for (int f = 0; f < 6; ++f) bad |= _mm512_fpclass_ps_mask(_mm512_load_ps(rows[f]), 0x99);
    bad |= _mm512_fpclass_ps_mask(_mm512_load_ps(rows[6]), 0x81);
    bad |= _mm512_fpclass_ps_mask(_mm512_load_ps(rows[7]), 0x81);
    return lanes & ~bad;
  }
  // The union of the N <= 16 child boxes of a node (bounds rows b[0..5]).
  template <int N>
  static RAYVEC_INLINE void union_box(const float (*b)[N], float lo[3], float hi[3]) {
    const __mmask16 m = __mmask16((1u << N) - 1u);
    for (int a = 0; a < 3; ++a) {
      lo[a] = _mm512_mask_reduce_min_ps(m, _mm512_maskz_loadu_ps(m, b[a]));
      hi[a] = _mm512_mask_reduce_max_ps(m, _mm512_maskz_loadu_ps(m, b[a + 3]));
    }
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = _mm512_loadu_ps(t); }
  // The smallest of tn over `lanes` (nonzero), and the largest current tmax over `lanes`.
  static RAYVEC_INLINE float min_lanes(const float* tn, unsigned lanes) {
    return _mm512_mask_reduce_min_ps(__mmask16(lanes), _mm512_loadu_ps(tn));
  }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const {
    return _mm512_mask_reduce_max_ps(__mmask16(lanes), tmax);
  }

  // Lanes (within `active`) whose ray overlaps child k's box of a node with N children; tn receives
  // each lane's entry distance.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float eps,
                               float* tn_out) const {
    const __m512 lx = _mm512_set1_ps(b[0][k]), ly = _mm512_set1_ps(b[1][k]), lz = _mm512_set1_ps(b[2][k]);
    const __m512 hx = _mm512_set1_ps(b[3][k]), hy = _mm512_set1_ps(b[4][k]), hz = _mm512_set1_ps(b[5][k]);
    const __m512 tnx = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(nx, lx, hx), ox), rx);
    const __m512 tny = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(ny, ly, hy), oy), ry);
    const __m512 tnz = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(nz, lz, hz), oz), rz);
    const __m512 tfx = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(nx, hx, lx), ox), rx);
    const __m512 tfy = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(ny, hy, ly), oy), ry);
    const __m512 tfz = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(nz, hz, lz), oz), rz);
    __m512 tn = _mm512_max_ps(tnx, _mm512_set1_ps(-__builtin_inff()));
    tn = _mm512_max_ps(tny, tn);
    tn = _mm512_max_ps(tnz, tn);
    __m512 tf = _mm512_min_ps(tfx, _mm512_set1_ps(__builtin_inff()));
    tf = _mm512_min_ps(tfy, tf);
    tf = _mm512_min_ps(tfz, tf);
    const __m512 e = _mm512_set1_ps(eps);
    tn = _mm512_fnmadd_ps(Zmm::abs(tn), e, tn);
    tf = _mm512_fmadd_ps(Zmm::abs(tf), e, tf);
    const __m512 lo = _mm512_max_ps(tmin, tn);
    const __m512 hi = _mm512_min_ps(tmax, tf);
    _mm512_storeu_ps(tn_out, lo);
    return (unsigned(_mm512_cmp_ps_mask(lo, hi, _CMP_LE_OQ))) & active;
  }
};

// PacketLanes16's test for a packet with every tmin >= 0 whose slabs cannot overflow (the guard
// and the robustness argument are in bvh/bvh_packet.inl): each slab distance in one FMA,
// b·r' − k, with r' = 1/d·(1 ∓ eps) for the near and far planes and k = o·r' rounded outward, so
// neither widening nor a subtraction of o is left per child (Ize 2013 folds the widening into the
// reciprocals the same way). Uniform: every lane has the same direction signs, so the near and far
// planes are the same bounds rows for all lanes and no blend is needed.
template <bool Uniform>
struct PacketLanes16Forward {
  __m512 nrx, nry, nrz, frx, fry, frz, knx, kny, knz, kfx, kfy, kfz, tmin, tmax;
  __mmask16 sx, sy, sz;        // lanes whose direction is negative: near plane hi, far plane lo
  int nx, ny, nz, fx, fy, fz;  // Uniform: the bounds rows of the near and far planes

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax; neg[a]: the lanes with
  // rdir[a] < 0 (Uniform: none or all of the active lanes).
  static RAYVEC_INLINE PacketLanes16Forward load(const float* const soa[8], const unsigned neg[3],
                                                 float eps) {
    PacketLanes16Forward k;
    const __m512 dn = _mm512_set1_ps(1.0f - eps), up = _mm512_set1_ps(1.0f + eps);
    __m512* const nr[3] = {&k.nrx, &k.nry, &k.nrz};
    __m512* const fr[3] = {&k.frx, &k.fry, &k.frz};
    __m512* const kn[3] = {&k.knx, &k.kny, &k.knz};
    __m512* const kf[3] = {&k.kfx, &k.kfy, &k.kfz};
    for (int a = 0; a < 3; ++a) {
      const __m512 o = _mm512_loadu_ps(soa[a]), r = _mm512_loadu_ps(soa[3 + a]);
      *nr[a] = _mm512_mul_ps(r, dn);
      *fr[a] = _mm512_mul_ps(r, up);
      *kn[a] = outward(_mm512_mul_ps(o, *nr[a]), _mm512_set1_ps(1.0f));
      *kf[a] = outward(_mm512_mul_ps(o, *fr[a]), _mm512_set1_ps(-1.0f));
    }
    k.tmin = _mm512_loadu_ps(soa[6]);
    k.tmax = _mm512_loadu_ps(soa[7]);
    k.sx = __mmask16(neg[0]); k.sy = __mmask16(neg[1]); k.sz = __mmask16(neg[2]);
    k.nx = neg[0] ? 3 : 0; k.ny = neg[1] ? 4 : 1; k.nz = neg[2] ? 5 : 2;
    k.fx = neg[0] ? 0 : 3; k.fy = neg[1] ? 1 : 4; k.fz = neg[2] ? 2 : 5;
    return k;
  }
  // p moved away from zero-crossing toward `dir` (+1 up, −1 down) by more than its rounding
  // error: max(|p|·2^-22, 2^-149) is at least two ulps of a normal p and one subnormal step.
  static RAYVEC_INLINE __m512 outward(__m512 p, __m512 dir) {
    const __m512 step = _mm512_max_ps(_mm512_mul_ps(Zmm::abs(p), _mm512_set1_ps(0x1p-22f)),
                                      _mm512_set1_ps(0x1p-149f));
    return _mm512_fmadd_ps(step, dir, p);
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = _mm512_loadu_ps(t); }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const {
    return _mm512_mask_reduce_max_ps(__mmask16(lanes), tmax);
  }

  // As PacketLanes16::hits.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float* tn_out) const {
    __m512 bnx, bny, bnz, bfx, bfy, bfz;
    if constexpr (Uniform) {
      bnx = _mm512_set1_ps(b[nx][k]); bny = _mm512_set1_ps(b[ny][k]); bnz = _mm512_set1_ps(b[nz][k]);
      bfx = _mm512_set1_ps(b[fx][k]); bfy = _mm512_set1_ps(b[fy][k]); bfz = _mm512_set1_ps(b[fz][k]);
    } else {
      const __m512 lx = _mm512_set1_ps(b[0][k]), ly = _mm512_set1_ps(b[1][k]), lz = _mm512_set1_ps(b[2][k]);
      const __m512 hx = _mm512_set1_ps(b[3][k]), hy = _mm512_set1_ps(b[4][k]), hz = _mm512_set1_ps(b[5][k]);
      bnx = _mm512_mask_blend_ps(sx, lx, hx); bny = _mm512_mask_blend_ps(sy, ly, hy);
      bnz = _mm512_mask_blend_ps(sz, lz, hz);
      bfx = _mm512_mask_blend_ps(sx, hx, lx); bfy = _mm512_mask_blend_ps(sy, hy, ly);
      bfz = _mm512_mask_blend_ps(sz, hz, lz);
    }
    const __m512 tnx = _mm512_fmsub_ps(bnx, nrx, knx), tny = _mm512_fmsub_ps(bny, nry, kny);
    const __m512 tnz = _mm512_fmsub_ps(bnz, nrz, knz);
    const __m512 tfx = _mm512_fmsub_ps(bfx, frx, kfx), tfy = _mm512_fmsub_ps(bfy, fry, kfy);
    const __m512 tfz = _mm512_fmsub_ps(bfz, frz, kfz);
    const __m512 lo = _mm512_max_ps(_mm512_max_ps(tnx, tmin), _mm512_max_ps(tny, tnz));
    const __m512 hi = _mm512_min_ps(_mm512_min_ps(tfx, tmax), _mm512_min_ps(tfy, tfz));
    _mm512_storeu_ps(tn_out, lo);
    return unsigned(_mm512_cmp_ps_mask(lo, hi, _CMP_LE_OQ)) & active;
  }
};

}  // namespace rayvec::avx512
