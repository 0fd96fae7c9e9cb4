// TriangleKernels: the function table one (ISA, intersector) pair provides. Brute force calls it on the
// whole TriangleSoA, a BVH on each leaf's range; the table is chosen once (triangle_kernels.cpp) and never
// per ray.
#pragma once
#include <cstdint>

#include "kernels/intersector.h"
#include "platform/isa.h"
#include "kernels/triangle_soa.h"
#include "rays/ray.h"

namespace rayvec {

// Lets an any-hit query ignore some triangles (e.g. the ones touching the vertex whose visibility is
// asked). Called only for triangles that pass the intersection test, so misses cost nothing.
struct HitFilter {
  bool (*ignore)(const void* context, int32_t triangle_id);
  const void* context;
};

struct TriangleKernels {
  Isa isa;
  Intersector intersector;
  int width;  // triangles per SIMD step (16 AVX-512, 8 AVX2, 1 scalar; halved for double)

  // Any begin and end <= count are allowed; steps load whole blocks of W slots at multiples of W
  // (blocked rows, triangle_soa.h) and mask the lanes outside [begin, end), so a range starting on
  // a multiple of W (as BVH leaves do) saves the masked head step.

  // Closest hit of `ray` among slots [begin, end): replaces `hit` when a triangle is hit with
  // tmin <= t <= min(tmax, hit.t) and it is nearer than `hit` (equal t: lower id wins). `hit` must be
  // a miss or a previous result for the same ray.
  void (*closest)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit);

  // True as soon as any triangle in [begin, end) is hit with tmin <= t <= tmax (and, with a filter,
  // is not ignored by it). filter may be null.
  bool (*occluded)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray& ray,
                   const HitFilter* filter);

  // Optional (may be null): `closest` for two rays at once, rays[0..1] and hits[0..1], loading each
  // triangle step once for both. Same results as two `closest` calls. Used by closest_batch.
  void (*closest_pair)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray* rays,
                       Hit* hits) = nullptr;
};

// The table for an ISA the CPU supports (checked by the caller through isa_supported).
const TriangleKernels& triangle_kernels(Isa isa, Intersector intersector);

// Per-ISA entry points, each defined in its own unit (triangle_kernels_<isa>.cpp).
namespace scalar {
const TriangleKernels& triangle_kernels(Intersector intersector);
}
namespace avx2 {
const TriangleKernels& triangle_kernels(Intersector intersector);
}
namespace avx512 {
const TriangleKernels& triangle_kernels(Intersector intersector);
}

}  // namespace rayvec
