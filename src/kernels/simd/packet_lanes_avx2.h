// AVX2 packet lanes for bvh/bvh_packet.inl: 8 rays, one per ymm lane, against one child box of a
// wide node at a time (PacketLanes8: any tmin, the widening per child as BoxLanes8 does it;
// PacketLanes8Forward: tmin >= 0, one FMA a slab), plus the packet's setup (the AoS → SoA
// transpose of its rays, the root box). One of the only files that include <immintrin.h>;
// included only by *_avx2.cpp units after box_lanes_avx2.h, in namespace rayvec::avx2.
#pragma once
#include <immintrin.h>

#include <cstdint>

#include "kernels/simd/box_lanes_avx2.h"

namespace rayvec::avx2 {

template <bool Uniform>
struct PacketLanes8Forward;

// A packet of 8 rays, one per lane, for packet traversal (bvh/bvh_packet.inl): the same slab
// arithmetic as BoxLanes8, transposed — one child box against every lane. Each lane picks
// its near plane by the sign of its own direction, so a lane's answer equals the single-ray test's.
struct PacketLanes8 {
  static constexpr int P = 8;
  template <bool Uniform>
  using Forward = PacketLanes8Forward<Uniform>;
  __m256 ox, oy, oz, rx, ry, rz, tmin, tmax;


  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax.
  static RAYVEC_INLINE PacketLanes8 load(const float* const soa[8]) {
    PacketLanes8 k;
    k.ox = _mm256_loadu_ps(soa[0]); k.oy = _mm256_loadu_ps(soa[1]); k.oz = _mm256_loadu_ps(soa[2]);
    k.rx = _mm256_loadu_ps(soa[3]); k.ry = _mm256_loadu_ps(soa[4]); k.rz = _mm256_loadu_ps(soa[5]);
    k.tmin = _mm256_loadu_ps(soa[6]); k.tmax = _mm256_loadu_ps(soa[7]);

    return k;
  }
  // Transposes 8 rays of 8 floats each (the Ray layout: o, d, tmin, tmax; ray k at rays + 8k) into
  // rows[f][k], reading only the rays of `lanes` (the others' rows are 0). Returns the lanes of
  // `lanes` whose ray is traceable: finite origin and direction, tmin and tmax not NaN.
  // The classic 8×8 transpose: unpacklo/hi, shufps, vperm2f128, each stage trading one bit of the
  // register index (ray) for one bit of the lane index (field).
  static RAYVEC_INLINE unsigned load_rays(const float* rays, unsigned lanes, float (*rows)[8]) {
    __m256 r[8], s[8];
    for (int j = 0; j < 8; ++j)
      r[j] = (lanes >> j) & 1u ? _mm256_loadu_ps(rays + 8 * j) : _mm256_setzero_ps();
    for (int j = 0; j < 8; j += 2) {  // slot bit 0 becomes field bit 1
      s[j] = _mm256_unpacklo_ps(r[j], r[j + 1]);
      s[j + 1] = _mm256_unpackhi_ps(r[j], r[j + 1]);
    }
    for (int j : {0, 1, 4, 5}) {  // slot bit 1 becomes field bit 0
      r[j] = _mm256_shuffle_ps(s[j], s[j + 2], 0x44);
      r[j + 2] = _mm256_shuffle_ps(s[j], s[j + 2], 0xee);
    }
    for (int j = 0; j < 4; ++j) {  // slot bit 2 becomes field bit 2
      s[j] = _mm256_permute2f128_ps(r[j], r[j + 4], 0x20);
      s[j + 4] = _mm256_permute2f128_ps(r[j], r[j + 4], 0x31);
    }
    // slot (field bit 2, field bit 0, field bit 1)
    for (int f = 0; f < 8; ++f) _mm256_store_ps(rows[f], s[(f & 4) | ((f & 1) << 1) | ((f & 2) >> 1)]);
    const __m256 inf = _mm256_set1_ps(__builtin_inff()), sign = _mm256_set1_ps(-0.0f);
    __m256 bad = _mm256_cmp_ps(_mm256_load_ps(rows[6]), _mm256_load_ps(rows[6]), _CMP_UNORD_Q);
    bad = _mm256_or_ps(bad, _mm256_cmp_ps(_mm256_load_ps(rows[7]), _mm256_load_ps(rows[7]), _CMP_UNORD_Q));
    for (int f = 0; f < 6; ++f)  // not |x| < inf: NaN or infinite
      bad = _mm256_or_ps(bad,
                         _mm256_cmp_ps(_mm256_andnot_ps(sign, _mm256_load_ps(rows[f])), inf, _CMP_NLT_UQ));
    return lanes & ~unsigned(_mm256_movemask_ps(bad));
  }
  // The union of the N <= 8 or 16 child boxes of a node (bounds rows b[0..5]).
  template <int N>
  static RAYVEC_INLINE void union_box(const float (*b)[N], float lo[3], float hi[3]) {
    static_assert(N <= 8 || N == 16, "one or two ymm per bounds row");
    if constexpr (N == 16) {  // two full halves; unused slots (lo +inf, hi −inf) change nothing
      const __m256 sign = _mm256_set1_ps(-0.0f);
      for (int a = 0; a < 3; ++a) {
        lo[a] = hmin(_mm256_min_ps(_mm256_loadu_ps(b[a]), _mm256_loadu_ps(b[a] + 8)));
        hi[a] = -hmin(_mm256_min_ps(_mm256_xor_ps(_mm256_loadu_ps(b[a + 3]), sign),
                                    _mm256_xor_ps(_mm256_loadu_ps(b[a + 3] + 8), sign)));
      }
      return;
    }
    const __m256 keep = lane_mask((1u << N) - 1u), inf = _mm256_set1_ps(__builtin_inff());
    const __m256 sign = _mm256_set1_ps(-0.0f);
    for (int a = 0; a < 3; ++a) {  // rows of N < 8 floats are padded by the next row: masked off
      lo[a] = hmin(_mm256_blendv_ps(inf, _mm256_loadu_ps(b[a]), keep));
      hi[a] = -hmin(_mm256_blendv_ps(inf, _mm256_xor_ps(_mm256_loadu_ps(b[a + 3]), sign), keep));
    }
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = _mm256_loadu_ps(t); }
  // The smallest of tn over `lanes` (nonzero), and the largest current tmax over `lanes`.
  static RAYVEC_INLINE __m256 lane_mask(unsigned lanes) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i m = _mm256_and_si256(_mm256_set1_epi32(int(lanes)), bit);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(m, bit));
  }
  static RAYVEC_INLINE float hmin(__m256 v) {
    __m128 x = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    x = _mm_min_ps(x, _mm_movehl_ps(x, x));
    x = _mm_min_ss(x, _mm_shuffle_ps(x, x, 1));
    return _mm_cvtss_f32(x);
  }
  static RAYVEC_INLINE float min_lanes(const float* tn, unsigned lanes) {
    return hmin(_mm256_blendv_ps(_mm256_set1_ps(__builtin_inff()), _mm256_loadu_ps(tn), lane_mask(lanes)));
  }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const {
    const __m256 neg = _mm256_xor_ps(tmax, _mm256_set1_ps(-0.0f));
    return -hmin(_mm256_blendv_ps(_mm256_set1_ps(__builtin_inff()), neg, lane_mask(lanes)));
  }

  // Lanes (within `active`) whose ray overlaps child k's box of a node with N children; tn receives
  // each lane's entry distance.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float eps,
                               float* tn_out) const {
    const __m256 lx = _mm256_set1_ps(b[0][k]), ly = _mm256_set1_ps(b[1][k]), lz = _mm256_set1_ps(b[2][k]);
    const __m256 hx = _mm256_set1_ps(b[3][k]), hy = _mm256_set1_ps(b[4][k]), hz = _mm256_set1_ps(b[5][k]);
    const __m256 tnx = _mm256_mul_ps(_mm256_sub_ps(_mm256_blendv_ps(lx, hx, rx), ox), rx);
    const __m256 tny = _mm256_mul_ps(_mm256_sub_ps(_mm256_blendv_ps(ly, hy, ry), oy), ry);
    const __m256 tnz = _mm256_mul_ps(_mm256_sub_ps(_mm256_blendv_ps(lz, hz, rz), oz), rz);
    const __m256 tfx = _mm256_mul_ps(_mm256_sub_ps(_mm256_blendv_ps(hx, lx, rx), ox), rx);
    const __m256 tfy = _mm256_mul_ps(_mm256_sub_ps(_mm256_blendv_ps(hy, ly, ry), oy), ry);
    const __m256 tfz = _mm256_mul_ps(_mm256_sub_ps(_mm256_blendv_ps(hz, lz, rz), oz), rz);
    __m256 tn = _mm256_max_ps(tnx, _mm256_set1_ps(-__builtin_inff()));
    tn = _mm256_max_ps(tny, tn);
    tn = _mm256_max_ps(tnz, tn);
    __m256 tf = _mm256_min_ps(tfx, _mm256_set1_ps(__builtin_inff()));
    tf = _mm256_min_ps(tfy, tf);
    tf = _mm256_min_ps(tfz, tf);
    const __m256 e = _mm256_set1_ps(eps);
    tn = _mm256_fnmadd_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), tn), e, tn);
    tf = _mm256_fmadd_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), tf), e, tf);
    const __m256 lo = _mm256_max_ps(tmin, tn);
    const __m256 hi = _mm256_min_ps(tmax, tf);
    _mm256_storeu_ps(tn_out, lo);
    return (unsigned(_mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ)))) & active;
  }
};

// PacketLanes8's test for a packet with every tmin >= 0 whose slabs cannot overflow: each slab in
// one FMA, b·r' − k (see PacketLanes16Forward in box_lanes_avx512.h; the guard and the robustness
// argument are in bvh/bvh_packet.inl). Uniform: the same near and far bounds rows for every lane.
template <bool Uniform>
struct PacketLanes8Forward {
  __m256 nrx, nry, nrz, frx, fry, frz, knx, kny, knz, kfx, kfy, kfz, tmin, tmax;
  __m256 sx, sy, sz;           // all-ones in the lanes whose direction is negative
  int nx, ny, nz, fx, fy, fz;  // Uniform: the bounds rows of the near and far planes

  // From SoA arrays of P floats: o[0..2], rdir[0..2], tmin, tmax; neg[a]: the lanes with
  // rdir[a] < 0 (Uniform: none or all of the active lanes).
  static RAYVEC_INLINE PacketLanes8Forward load(const float* const soa[8], const unsigned neg[3],
                                                float eps) {
    PacketLanes8Forward k;
    const __m256 dn = _mm256_set1_ps(1.0f - eps), up = _mm256_set1_ps(1.0f + eps);
    __m256* const nr[3] = {&k.nrx, &k.nry, &k.nrz};
    __m256* const fr[3] = {&k.frx, &k.fry, &k.frz};
    __m256* const kn[3] = {&k.knx, &k.kny, &k.knz};
    __m256* const kf[3] = {&k.kfx, &k.kfy, &k.kfz};
    for (int a = 0; a < 3; ++a) {
      const __m256 o = _mm256_loadu_ps(soa[a]), r = _mm256_loadu_ps(soa[3 + a]);
      *nr[a] = _mm256_mul_ps(r, dn);
      *fr[a] = _mm256_mul_ps(r, up);
      *kn[a] = outward(_mm256_mul_ps(o, *nr[a]), _mm256_set1_ps(1.0f));
      *kf[a] = outward(_mm256_mul_ps(o, *fr[a]), _mm256_set1_ps(-1.0f));
    }
    k.tmin = _mm256_loadu_ps(soa[6]);
    k.tmax = _mm256_loadu_ps(soa[7]);
    k.sx = PacketLanes8::lane_mask(neg[0]);
    k.sy = PacketLanes8::lane_mask(neg[1]);
    k.sz = PacketLanes8::lane_mask(neg[2]);
    k.nx = neg[0] ? 3 : 0; k.ny = neg[1] ? 4 : 1; k.nz = neg[2] ? 5 : 2;
    k.fx = neg[0] ? 0 : 3; k.fy = neg[1] ? 1 : 4; k.fz = neg[2] ? 2 : 5;
    return k;
  }
  // p moved toward `dir` (+1 up, −1 down) by more than its rounding error (see PacketLanes16Forward).
  static RAYVEC_INLINE __m256 outward(__m256 p, __m256 dir) {
    const __m256 a = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), p);
    const __m256 step = _mm256_max_ps(_mm256_mul_ps(a, _mm256_set1_ps(0x1p-22f)), _mm256_set1_ps(0x1p-149f));
    return _mm256_fmadd_ps(step, dir, p);
  }
  RAYVEC_INLINE void set_tmax(const float* t) { tmax = _mm256_loadu_ps(t); }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const {
    const __m256 neg = _mm256_xor_ps(tmax, _mm256_set1_ps(-0.0f));
    return -PacketLanes8::hmin(
        _mm256_blendv_ps(_mm256_set1_ps(__builtin_inff()), neg, PacketLanes8::lane_mask(lanes)));
  }

  // As PacketLanes8::hits.
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float* tn_out) const {
    __m256 bnx, bny, bnz, bfx, bfy, bfz;
    if constexpr (Uniform) {
      bnx = _mm256_set1_ps(b[nx][k]); bny = _mm256_set1_ps(b[ny][k]); bnz = _mm256_set1_ps(b[nz][k]);
      bfx = _mm256_set1_ps(b[fx][k]); bfy = _mm256_set1_ps(b[fy][k]); bfz = _mm256_set1_ps(b[fz][k]);
    } else {
      const __m256 lx = _mm256_set1_ps(b[0][k]), ly = _mm256_set1_ps(b[1][k]), lz = _mm256_set1_ps(b[2][k]);
      const __m256 hx = _mm256_set1_ps(b[3][k]), hy = _mm256_set1_ps(b[4][k]), hz = _mm256_set1_ps(b[5][k]);
      bnx = _mm256_blendv_ps(lx, hx, sx); bny = _mm256_blendv_ps(ly, hy, sy);
      bnz = _mm256_blendv_ps(lz, hz, sz);
      bfx = _mm256_blendv_ps(hx, lx, sx); bfy = _mm256_blendv_ps(hy, ly, sy);
      bfz = _mm256_blendv_ps(hz, lz, sz);
    }
    const __m256 tnx = _mm256_fmsub_ps(bnx, nrx, knx), tny = _mm256_fmsub_ps(bny, nry, kny);
    const __m256 tnz = _mm256_fmsub_ps(bnz, nrz, knz);
    const __m256 tfx = _mm256_fmsub_ps(bfx, frx, kfx), tfy = _mm256_fmsub_ps(bfy, fry, kfy);
    const __m256 tfz = _mm256_fmsub_ps(bfz, frz, kfz);
    const __m256 lo = _mm256_max_ps(_mm256_max_ps(tnx, tmin), _mm256_max_ps(tny, tnz));
    const __m256 hi = _mm256_min_ps(_mm256_min_ps(tfx, tmax), _mm256_min_ps(tfy, tfz));
    _mm256_storeu_ps(tn_out, lo);
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ))) & active;
  }
};

}  // namespace rayvec::avx2
