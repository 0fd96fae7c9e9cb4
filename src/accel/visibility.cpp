#include "accel/visibility.h"

#include <cmath>
#include <limits>

namespace rayvec {
namespace {

struct OwnVertex {
  const TriangleMesh* mesh;
  Vec3f position;
};

// A triangle touching the vertex ends exactly at it: whether it "crosses" the segment there is
// pure rounding, so it never blocks.
bool touches_vertex(const void* context, int32_t tri) {
  const auto& own = *static_cast<const OwnVertex*>(context);
  const auto& corners = own.mesh->triangles[static_cast<std::size_t>(tri)];
  for (uint32_t index : corners)
    if (own.mesh->positions[index] == own.position) return true;
  return false;
}

}  // namespace

VisibilityMesh build_visibility_mesh(const std::vector<Vec3f>& verts,
                                     const std::vector<std::array<uint32_t, 3>>& faces) {
  VisibilityMesh out;
  out.mesh.positions = verts;
  // Unused by any kept face, but a structure builder may scan every position: keep them finite.
  for (Vec3f& p : out.mesh.positions)
    if (!is_finite(p)) p = Vec3f{};
  out.mesh.triangles.reserve(faces.size());
  for (const auto& face : faces) {
    if (is_finite(verts[face[0]]) && is_finite(verts[face[1]]) && is_finite(verts[face[2]]))
      out.mesh.triangles.push_back(face);
    else
      ++out.dropped;
  }
  return out;
}

std::vector<Visibility> compute_visibility(const Accelerator& accel, const TriangleMesh& mesh,
                                           const std::vector<Vec3f>& verts, Vec3f origin) {
  // Open segment: t = 0 (the origin) and t = 1 (the vertex) excluded, everything between included.
  const float t_open_start = std::numeric_limits<float>::denorm_min();
  const float t_open_end = std::nextafter(1.0f, 0.0f);
  std::vector<Visibility> result(verts.size());
  const auto n = static_cast<std::int64_t>(verts.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (std::int64_t i = 0; i < n; ++i) {
    const Vec3f p = verts[static_cast<std::size_t>(i)];
    if (!is_finite(p)) {
      result[i] = Visibility::undefined;
      continue;
    }
    const OwnVertex own{&mesh, p};
    const HitFilter filter{&touches_vertex, &own};
    const Ray ray{origin, p - origin, t_open_start, t_open_end};
    result[i] = accel.occluded(ray, &filter) ? Visibility::blocked : Visibility::visible;
  }
  return result;
}

}  // namespace rayvec
