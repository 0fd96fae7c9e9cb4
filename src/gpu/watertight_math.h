// Watertight ray–triangle intersection (Woop, Benthin & Wald 2013) for one ray and one triangle: the
// arithmetic of the CPU kernels in kernels/watertight.inl (test_watertight) written out for a single
// lane, for the device and the host alike. S = float is intersector `watertight` (with the double
// refinement of exactly-zero edge functions and the bound on t's rounding error), S = double is
// `watertight64`. No fused multiply-add anywhere, as on the CPU: the same bits on every ISA and on
// the device (compiled with --fmad=false, device_math.h).
#pragma once
#include "gpu/gpu_ray.h"

namespace rayvec::gpu {

template <class S>
struct WatertightMath {
  using Real = S;
  struct Ray {
    uint32_t kx, ky, kz;  // the permutation: kz = axis of largest |d|
    S ox, oy, oz;         // origin, permuted
    S sx, sy, sz;         // shear: Sx, Sy, Sz of the paper
    S tmin;
    bool valid;
  };

  static RAYVEC_HD Ray prepare(const GpuRay& r) {
    const float d[3] = {r.dx, r.dy, r.dz};
    const float o[3] = {r.ox, r.oy, r.oz};
    const float ad[3] = {d[0] < 0 ? -d[0] : d[0], d[1] < 0 ? -d[1] : d[1], d[2] < 0 ? -d[2] : d[2]};
    // permutation: kz = axis of largest |d|; swap kx, ky when d[kz] < 0 (keeps the winding)
    uint32_t kz = ad[0] > ad[1] ? (ad[0] > ad[2] ? 0 : 2) : (ad[1] > ad[2] ? 1 : 2);
    uint32_t kx = kz == 2 ? 0 : kz + 1;
    uint32_t ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0) {
      const uint32_t k = kx;
      kx = ky;
      ky = k;
    }
    const S dz = S(d[kz]);
    return {kx,        ky,        kz,           S(o[kx]), S(o[ky]), S(o[kz]), S(d[kx]) / dz, S(d[ky]) / dz,
            S(1) / dz, S(r.tmin), finite_ray(r)};
  }

  // True when the triangle has exactly zero area (e1 × e2 = 0 for the exact vertices): shearing
  // rounds a collinear triangle into a sliver of nonzero area in ray space. Compared as two-products
  // (equal rounded products and equal exact errors).
  static RAYVEC_HD bool same_product(double a, double b, double c, double d) {
    const double p = a * b, q = c * d;
    return p == q && fused(a, b, -p) == fused(c, d, -q);
  }
  static RAYVEC_HD bool zero_area(const TriangleView& t) {
    const double e1x = double(t.at(kV1x)) - t.at(kV0x), e1y = double(t.at(kV1y)) - t.at(kV0y),
                 e1z = double(t.at(kV1z)) - t.at(kV0z);
    const double e2x = double(t.at(kV2x)) - t.at(kV0x), e2y = double(t.at(kV2y)) - t.at(kV0y),
                 e2z = double(t.at(kV2z)) - t.at(kV0z);
    return same_product(e1y, e2z, e1z, e2y) && same_product(e1z, e2x, e1x, e2z) &&
           same_product(e1x, e2y, e1y, e2x);
  }

  // The bound on the rounding error of t = T/|det| (watertight.inl, watertight_t_error): a hit is
  // reported only beyond it, so a ray leaving a surface never finds that surface again.
  static RAYVEC_HD S max3(S a, S b, S c) { return max_x86(max_x86(abs_bits(a), abs_bits(b)), abs_bits(c)); }
  static RAYVEC_HD S gamma(int n) {
    const S eps = S(0x1p-24);  // unit roundoff of float
    return S(n) * eps / (S(1) - S(n) * eps);
  }
  static RAYVEC_HD S t_error(S ax, S ay, S az, S bx, S by, S bz, S cx, S cy, S cz, S sz, S adet) {
    const S za = sz * az, zb = sz * bz, zc = sz * cz;
    const S max_z = max3(za, zb, zc), max_x = max3(ax, bx, cx), max_y = max3(ay, by, cy);
    const S spread_z = max3(za - zb, zb - zc, zc - za);
    const S max_dz = max3(az, bz, cz);
    const S delta_x = gamma(5) * (max_x + max_dz), delta_y = gamma(5) * (max_y + max_dz);
    const S delta_e = S(2) * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    return S(7) * gamma(3) * max_z + S(5) * delta_e * spread_z / adet;
  }

  // A hit with tmin <= t < tlimit beyond t's rounding error: t, and the barycentrics of v1 and v2.
  static RAYVEC_HD bool test(const Ray& r, const TriangleView& tri, S tlimit, S& t, S& u, S& v) {
    // translate to the ray origin (exact vertices), z stays unsheared until needed
    const S az = S(tri.at(kV0x + r.kz)) - r.oz, bz = S(tri.at(kV1x + r.kz)) - r.oz,
            cz = S(tri.at(kV2x + r.kz)) - r.oz;
    // shear into ray space (separate multiply and subtract)
    const S ax = (S(tri.at(kV0x + r.kx)) - r.ox) - r.sx * az;
    const S ay = (S(tri.at(kV0x + r.ky)) - r.oy) - r.sy * az;
    const S bx = (S(tri.at(kV1x + r.kx)) - r.ox) - r.sx * bz;
    const S by = (S(tri.at(kV1x + r.ky)) - r.oy) - r.sy * bz;
    const S cx = (S(tri.at(kV2x + r.kx)) - r.ox) - r.sx * cz;
    const S cy = (S(tri.at(kV2x + r.ky)) - r.oy) - r.sy * cz;
    // 2D edge functions
    S eu = cx * by - cy * bx;
    S ev = ax * cy - ay * cx;
    S ew = bx * ay - by * ax;
    // edge tests (closed): every edge function has the sign of det
    S det = eu + ev + ew;
    auto sign = sign_of(det);
    if (!(flip(eu, sign) >= S(0) && flip(ev, sign) >= S(0) && flip(ew, sign) >= S(0))) return false;
    if constexpr (sizeof(S) == 4) {  // float: refine exact zeros in double (Woop et al. 2013, §3)
      if (eu == S(0) || ev == S(0) || ew == S(0)) {
        const double Ax = ax, Ay = ay, Bx = bx, By = by, Cx = cx, Cy = cy;
        eu = S(Cx * By - Cy * Bx);
        ev = S(Ax * Cy - Ay * Cx);
        ew = S(Bx * Ay - By * Ax);
        det = eu + ev + ew;
        sign = sign_of(det);
        if (!(flip(eu, sign) >= S(0) && flip(ev, sign) >= S(0) && flip(ew, sign) >= S(0))) return false;
      }
    }
    // det != 0 and finite (ordered compares also drop NaN)
    const S adet = abs_bits(det);
    if (!(adet > S(0) && adet < infinity<S>())) return false;
    // depth test: t = (U·Az + V·Bz + W·Cz) / det with the scaled z
    const S tn = flip(eu * (r.sz * az) + ev * (r.sz * bz) + ew * (r.sz * cz), sign);
    t = tn / adet;
    if (!(t >= r.tmin && t < tlimit)) return false;
    if constexpr (sizeof(S) == 4)
      if (!(t > t_error(ax, ay, az, bx, by, bz, cx, cy, cz, r.sz, adet))) return false;
    if (zero_area(tri)) return false;
    u = flip(ev, sign) / adet;
    v = flip(ew, sign) / adet;
    return true;
  }
};

}  // namespace rayvec::gpu
