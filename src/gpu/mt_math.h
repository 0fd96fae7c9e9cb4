// Möller–Trumbore for one ray and one triangle: the arithmetic of the CPU kernels
// (kernels/mt_float.inl, kernels/moller_trumbore.inl) written out for a single lane, for the device
// and the host alike.
//   MtFloat  — intersector `mt`: closest_mt_float / occluded_mt_float, over the precomputed normal
//              (det = d·ng, u·det = −(e2·c), v·det = e1·c, t·det = s·ng with s = v0 − o, c = s × d).
//   MtDouble — intersector `mt64`: test_mt over vdouble, edges formed in double from the vertices.
// Each keeps only the exact tests of its CPU kernel: the CPU's division-free depth pre-tests are
// conservative (every lane that passes the exact tests passes them), so they change the speed,
// not the answer. Fused selects the multiply-add rounding (device_math.h): true on the device, as
// the AVX2 and AVX-512 kernels; false reproduces the scalar ISA kernel.
#pragma once
#include "gpu/gpu_ray.h"

namespace rayvec::gpu {

template <bool Fused>
struct MtFloat {
  using Real = float;
  struct Ray {
    float ox, oy, oz, dx, dy, dz, tmin, tmax;
    bool valid;
  };
  static RAYVEC_HD Ray prepare(const GpuRay& r) {
    return {r.ox, r.oy, r.oz, r.dx, r.dy, r.dz, r.tmin, r.tmax, finite_ray(r)};
  }
  // A hit with tmin <= t < tlimit: t, and the barycentrics of v1 and v2.
  static RAYVEC_HD bool test(const Ray& r, const TriangleView& tri, float tlimit, float& t, float& u,
                             float& v) {
    // s = v0 − o, c = s × d
    const float v0x = tri.at(kV0x), v0y = tri.at(kV0y), v0z = tri.at(kV0z);
    const float sx = v0x - r.ox, sy = v0y - r.oy, sz = v0z - r.oz;
    const float cx = msub<Fused>(sy, r.dz, sz * r.dy);
    const float cy = msub<Fused>(sz, r.dx, sx * r.dz);
    const float cz = msub<Fused>(sx, r.dy, sy * r.dx);
    // det = d · ng
    const float ngx = tri.at(kNgx), ngy = tri.at(kNgy), ngz = tri.at(kNgz);
    const float det = madd<Fused>(r.dx, ngx, madd<Fused>(r.dy, ngy, r.dz * ngz));
    const uint32_t sign = sign_of(det);
    const float adet = abs_bits(det);
    // numerators with det's sign folded in; un = −u·|det|
    const float e2x = tri.at(kV2x) - v0x, e2y = tri.at(kV2y) - v0y, e2z = tri.at(kV2z) - v0z;
    const float un = flip(madd<Fused>(e2x, cx, madd<Fused>(e2y, cy, e2z * cz)), sign);
    const float e1x = tri.at(kV1x) - v0x, e1y = tri.at(kV1y) - v0y, e1z = tri.at(kV1z) - v0z;
    const float vn = flip(madd<Fused>(e1x, cx, madd<Fused>(e1y, cy, e1z * cz)), sign);
    // edge tests (closed), det != 0; ordered compares reject NaN
    if (!(un <= 0.0f && vn >= 0.0f && vn - un <= adet && adet > 0.0f)) return false;
    // depth test
    const float tn = flip(madd<Fused>(sx, ngx, madd<Fused>(sy, ngy, sz * ngz)), sign);
    t = tn / adet + 0.0f;  // + 0: no −0, as the CPU kernels report a hit at t = 0
    if (!(t >= r.tmin && t < tlimit)) return false;
    u = (0.0f - un) / adet;  // 0 − un: no −0
    v = vn / adet;
    return true;
  }
};

template <bool Fused>
struct MtDouble {
  using Real = double;
  struct Ray {
    double ox, oy, oz, dx, dy, dz, tmin;
    float tmax;
    bool valid;
  };
  static RAYVEC_HD Ray prepare(const GpuRay& r) {
    return {r.ox, r.oy, r.oz, r.dx, r.dy, r.dz, r.tmin, r.tmax, finite_ray(r)};
  }
  static RAYVEC_HD bool test(const Ray& r, const TriangleView& tri, double tlimit, double& t, double& u,
                             double& v) {
    const double v0x = tri.at(kV0x), v0y = tri.at(kV0y), v0z = tri.at(kV0z);
    // edges from the exact vertices, in double
    const double e1x = double(tri.at(kV1x)) - v0x, e1y = double(tri.at(kV1y)) - v0y,
                 e1z = double(tri.at(kV1z)) - v0z;
    const double e2x = double(tri.at(kV2x)) - v0x, e2y = double(tri.at(kV2y)) - v0y,
                 e2z = double(tri.at(kV2z)) - v0z;
    // h = d × e2, det = e1 · h
    const double hx = msub<Fused>(r.dy, e2z, r.dz * e2y);
    const double hy = msub<Fused>(r.dz, e2x, r.dx * e2z);
    const double hz = msub<Fused>(r.dx, e2y, r.dy * e2x);
    const double det = madd<Fused>(e1x, hx, madd<Fused>(e1y, hy, e1z * hz));
    // u·det = s · h, v·det = d · (s × e1)
    const double sx = r.ox - v0x, sy = r.oy - v0y, sz = r.oz - v0z;
    const double qx = msub<Fused>(sy, e1z, sz * e1y);
    const double qy = msub<Fused>(sz, e1x, sx * e1z);
    const double qz = msub<Fused>(sx, e1y, sy * e1x);
    const uint64_t sign = sign_of(det);
    const double adet = abs_bits(det);
    const double un = flip(madd<Fused>(sx, hx, madd<Fused>(sy, hy, sz * hz)), sign);
    const double vn = flip(madd<Fused>(r.dx, qx, madd<Fused>(r.dy, qy, r.dz * qz)), sign);
    // edge tests (closed), det != 0
    if (!(un >= 0.0 && vn >= 0.0 && un + vn <= adet && adet > 0.0)) return false;
    // depth test
    const double tn = flip(madd<Fused>(e2x, qx, madd<Fused>(e2y, qy, e2z * qz)), sign);
    t = tn / adet;
    if (!(t >= r.tmin && t < tlimit)) return false;
    u = un / adet;
    v = vn / adet;
    return true;
  }
};

}  // namespace rayvec::gpu
