// The device math run on the host: the loops of trace_loops.h over a GpuTriangles, one ray at a
// time. The Cuda* tests compare it with the CPU kernels (fused = false against the scalar ISA,
// fused = true — the device's rounding — against AVX2 and AVX-512): a test subject, not a product
// path.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/gpu_scene.h"
#include "kernels/intersector.h"
#include "rays/ray.h"

namespace rayvec::gpu {

enum class HostLayout { aos, soa };

// Closest hit per ray. Throws std::invalid_argument for an intersector the device lacks.
std::vector<Hit> host_closest(const GpuTriangles& tris, std::span<const Ray> rays, Intersector intersector,
                              bool fused, HostLayout layout = HostLayout::aos);

// Any hit per ray (1/0); with `ignore` (one point per ray), triangles with a corner at the ray's
// point are left out, as the visibility filter does.
std::vector<uint8_t> host_occluded(const GpuTriangles& tris, std::span<const Ray> rays, const Vec3f* ignore,
                                   Intersector intersector, bool fused, HostLayout layout = HostLayout::aos);

}  // namespace rayvec::gpu
