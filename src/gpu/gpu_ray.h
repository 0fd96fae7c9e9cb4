// What the device kernels read and write: rays and hits as plain structs (the host's Ray and Hit
// have the same fields; gpu_scene.cpp converts), and a view of one triangle in either layout the
// kernels use — 12 floats per triangle (AoS: global memory and the shared tiles of the study) or
// 12 rows of floats (SoA: in global memory and in the SoA shared tiles).
#pragma once
#include <cstdint>

#include "gpu/device_math.h"

namespace rayvec::gpu {

// A ray o + t·d for tmin <= t <= tmax, as rays/ray.h.
struct GpuRay {
  float ox, oy, oz, dx, dy, dz, tmin, tmax;
};

// A closest hit, as rays/ray.h's Hit: a miss is tri −1, t +inf.
struct GpuHit {
  float t, u, v;
  int32_t tri;
};

// The 12 values stored per triangle: the exact vertices and the normal ng = e2 × e1 that the float
// `mt` arithmetic reads (computed on the host by the very expression TriangleSoA's fill uses).
enum TriangleRow : uint32_t {
  kV0x = 0,
  kV0y,
  kV0z,
  kV1x,
  kV1y,
  kV1z,
  kV2x,
  kV2y,
  kV2z,
  kNgx,
  kNgy,
  kNgz,
  kTriangleRows
};

// Triangle values at p[row · stride]: stride 1 for AoS records, the row length for SoA rows.
struct TriangleView {
  const float* p;
  uint32_t stride;
  RAYVEC_HD float at(uint32_t row) const { return p[row * stride]; }
};

// False when the ray can never hit (the CPU kernels' finite_ray): a NaN or Inf in its origin or
// direction, or a NaN tmin or tmax.
RAYVEC_HD bool finite_ray(const GpuRay& r) {
  const float big = 3.4028235e38f;
  const float c[6] = {r.ox, r.oy, r.oz, r.dx, r.dy, r.dz};
  for (float x : c)
    if (!(x >= -big && x <= big)) return false;
  return r.tmin == r.tmin && r.tmax == r.tmax;
}

// True when a corner of the triangle is exactly at p (the visibility filter: a vertex's own
// triangles never block it).
RAYVEC_HD bool has_corner_at(const TriangleView& t, float px, float py, float pz) {
  for (uint32_t c = 0; c < 3; ++c)
    if (t.at(kV0x + 3 * c) == px && t.at(kV0y + 3 * c) == py && t.at(kV0z + 3 * c) == pz) return true;
  return false;
}

}  // namespace rayvec::gpu
