#include "gpu/gpu_scene.h"

#include <limits>
#include <stdexcept>

namespace rayvec::gpu {

GpuTriangles make_gpu_triangles(const TriangleMesh& mesh) {
  if (mesh.size() > std::size_t(std::numeric_limits<int32_t>::max()))
    throw std::length_error("too many triangles for the device (at most 2^31 - 1)");
  GpuTriangles out;
  out.count = uint32_t(mesh.size());
  out.row_length = (out.count + 31) / 32 * 32;
  out.aos.resize(std::size_t(out.count) * kTriangleRows);
  out.soa.assign(std::size_t(out.row_length) * kTriangleRows, 0.0f);
  for (uint32_t i = 0; i < out.count; ++i) {
    // as TriangleSoA's fill: e1, e2 and ng = e2 × e1 in float (math/vec3.h)
    const Vec3f p0 = mesh.vertex(i, 0), p1 = mesh.vertex(i, 1), p2 = mesh.vertex(i, 2);
    const Vec3f e1 = p1 - p0, e2 = p2 - p0, ng = cross(e2, e1);
    const float values[kTriangleRows] = {p0.x, p0.y, p0.z, p1.x, p1.y, p1.z,
                                         p2.x, p2.y, p2.z, ng.x, ng.y, ng.z};
    for (uint32_t row = 0; row < kTriangleRows; ++row) {
      out.aos[std::size_t(i) * kTriangleRows + row] = values[row];
      out.soa[std::size_t(row) * out.row_length + i] = values[row];
    }
  }
  return out;
}

GpuRay to_gpu_ray(const Ray& r) {
  return {r.org.x, r.org.y, r.org.z, r.dir.x, r.dir.y, r.dir.z, r.tmin, r.tmax};
}

std::vector<GpuRay> to_gpu_rays(std::span<const Ray> rays) {
  std::vector<GpuRay> out(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) out[i] = to_gpu_ray(rays[i]);
  return out;
}

Hit to_hit(const GpuHit& h) { return Hit{h.t, h.u, h.v, h.tri}; }

}  // namespace rayvec::gpu
