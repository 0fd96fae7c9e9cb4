// Scalar ray–box test for the wide BVH: the same arithmetic as box_lanes_avx2.h / _avx512.h, one
// child at a time, for baseline x86-64. Included only by *_scalar.cpp units, in namespace
// rayvec::scalar. The robustness argument is documented in bvh/single_ray_traversal.inl.
#pragma once
#include <cstdint>

#include "platform/attributes.h"

namespace rayvec::scalar {

struct BoxLanesRay {
  float o[3], r[3];
  int near[3], far[3];
};

// For rays with tmin >= 0: the reciprocals of the near and far planes, already scaled by (1 ∓ eps).
struct BoxLanesForwardRay {
  float o[3], nr[3], fr[3];
  int near[3], far[3];
};

template <int W>
struct BoxLanes {
  static constexpr int N = W;
  using RayData = BoxLanesRay;
  using ForwardRay = BoxLanesForwardRay;

  static RAYVEC_INLINE ForwardRay prepare_forward(const float o[3], const float rdir[3], const int near[3],
                                                  float eps) {
    ForwardRay d;
    for (int a = 0; a < 3; ++a) {
      d.o[a] = o[a];
      d.nr[a] = rdir[a] * (1.0f - eps);
      d.fr[a] = rdir[a] * (1.0f + eps);
      d.near[a] = near[a];
      d.far[a] = near[a] < 3 ? near[a] + 3 : near[a] - 3;
    }
    return d;
  }

  // As hits() for a ray with tmin >= 0, the widening done by the scaled reciprocals.
  static RAYVEC_INLINE unsigned hits_forward(const float (*b)[W], const ForwardRay& r, float tmin,
                                             float tmax, float* dist) {
    unsigned mask = 0;
    for (int k = 0; k < W; ++k) {
      float lo = tmin, hi = tmax;
      for (int a = 0; a < 3; ++a) {
        const float n = (b[r.near[a]][k] - r.o[a]) * r.nr[a];
        const float f = (b[r.far[a]][k] - r.o[a]) * r.fr[a];
        if (n > lo) lo = n;  // a NaN slab (0·inf) fails the comparison and is skipped
        if (f < hi) hi = f;
      }
      dist[k] = lo;
      if (lo <= hi) mask |= 1u << k;
    }
    return mask;
  }

  static RAYVEC_INLINE RayData prepare(const float o[3], const float rdir[3], const int near[3]) {
    RayData d;
    for (int a = 0; a < 3; ++a) {
      d.o[a] = o[a];
      d.r[a] = rdir[a];
      d.near[a] = near[a];
      d.far[a] = near[a] < 3 ? near[a] + 3 : near[a] - 3;
    }
    return d;
  }

  static RAYVEC_INLINE unsigned hits(const float (*b)[W], const RayData& r, float tmin, float tmax,
                                     float eps, float* dist) {
    unsigned mask = 0;
    for (int k = 0; k < W; ++k) {
      float tn = -__builtin_inff(), tf = __builtin_inff();
      for (int a = 0; a < 3; ++a) {
        const float n = (b[r.near[a]][k] - r.o[a]) * r.r[a];
        const float f = (b[r.far[a]][k] - r.o[a]) * r.r[a];
        if (n > tn) tn = n;  // a NaN slab (0·inf) fails the comparison and is skipped
        if (f < tf) tf = f;
      }
      tn = tn - (tn < 0 ? -tn : tn) * eps;  // infinite ends become NaN and miss
      tf = tf + (tf < 0 ? -tf : tf) * eps;
      const float lo = tn == tn && tn > tmin ? tn : (tn == tn ? tmin : tn);
      const float hi = tf == tf && tf < tmax ? tf : (tf == tf ? tmax : tf);
      dist[k] = lo;
      if (lo <= hi) mask |= 1u << k;
    }
    return mask;
  }
};

}  // namespace rayvec::scalar
