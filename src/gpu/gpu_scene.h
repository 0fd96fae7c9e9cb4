// The host side of the device data: a mesh as the 12 values per triangle of gpu_ray.h (vertices and
// the normal ng, computed by the expression TriangleSoA's fill uses, so both see the same bits) in
// the two layouts the kernels read, and rays converted to GpuRay. Plain C++: built in every
// configuration, used by the CUDA backend and by the host reference.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "gpu/gpu_ray.h"
#include "rays/ray.h"

namespace rayvec::gpu {

struct GpuTriangles {
  uint32_t count = 0;
  uint32_t row_length = 0;  // SoA row length: count rounded up to a multiple of 32 (aligned rows)
  std::vector<float> aos;   // count records of kTriangleRows floats
  std::vector<float> soa;   // kTriangleRows rows of row_length floats (zero-area padding)

  TriangleView aos_view(uint32_t i) const { return {aos.data() + std::size_t(i) * kTriangleRows, 1}; }
  TriangleView soa_view(uint32_t i) const { return {soa.data() + i, row_length}; }
};

// Throws std::length_error beyond 2^31 − 1 triangles (ids are int32).
GpuTriangles make_gpu_triangles(const TriangleMesh& mesh);

GpuRay to_gpu_ray(const Ray& r);
std::vector<GpuRay> to_gpu_rays(std::span<const Ray> rays);
Hit to_hit(const GpuHit& h);

}  // namespace rayvec::gpu
