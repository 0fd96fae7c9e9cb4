// One ray against triangles [begin, end) of a view, closest hit or any hit, over an intersector's
// single-lane math (mt_math.h, watertight_math.h). The device kernels run these loops over global
// memory or over a shared tile; the host runs the same loops in the tests that check the math
// against the CPU kernels. Triangle ids are the positions: the loops visit them in increasing order
// and keep a hit only when strictly nearer, so at equal t the lowest id wins, as on the CPU.
#pragma once
#include "gpu/gpu_ray.h"

namespace rayvec::gpu {

// The running closest hit of one ray, in the intersector's precision.
template <class Math>
struct ClosestState {
  using Real = typename Math::Real;
  Real t, u, v;
  int32_t tri;
};

template <class Math>
RAYVEC_HD ClosestState<Math> closest_start(const GpuRay& ray) {
  using Real = typename Math::Real;
  // as the CPU kernels: hits with t <= tmax, that is t < next_up(tmax) in the kernel's precision
  return {next_up(Real(ray.tmax)), Real(0), Real(0), -1};
}

// `triangle(i)` gives the TriangleView of triangle i (its id is i + id_base).
template <class Math, class TriangleAt>
RAYVEC_HD void closest_range(const typename Math::Ray& r, const TriangleAt& triangle, uint32_t begin,
                             uint32_t end, int32_t id_base, ClosestState<Math>& best) {
  using Real = typename Math::Real;
  for (uint32_t i = begin; i < end; ++i) {
    Real t, u, v;
    if (Math::test(r, triangle(i), best.t, t, u, v)) best = {t, u, v, int32_t(i) + id_base};
  }
}

template <class Math>
RAYVEC_HD GpuHit closest_finish(const ClosestState<Math>& best) {
  if (best.tri < 0) return {infinity<float>(), 0.0f, 0.0f, -1};
  return {float(best.t), float(best.u), float(best.v), best.tri};
}

// Any hit with tmin <= t <= tmax, triangles with a corner at `ignore` (when given) left out.
template <class Math, class TriangleAt>
RAYVEC_HD bool occluded_range(const typename Math::Ray& r, typename Math::Real tlimit,
                              const TriangleAt& triangle, uint32_t begin, uint32_t end, const float* ignore) {
  using Real = typename Math::Real;
  for (uint32_t i = begin; i < end; ++i) {
    Real t, u, v;
    const TriangleView tri = triangle(i);
    if (Math::test(r, tri, tlimit, t, u, v) &&
        !(ignore && has_corner_at(tri, ignore[0], ignore[1], ignore[2])))
      return true;
  }
  return false;
}

template <class Math>
RAYVEC_HD typename Math::Real occluded_limit(const GpuRay& ray) {
  using Real = typename Math::Real;
  return next_up(Real(ray.tmax));
}

}  // namespace rayvec::gpu
