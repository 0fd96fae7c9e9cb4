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

Ray visibility_ray(Vec3f origin, Vec3f vertex) {
  // Open segment: t = 0 (the origin) and t = 1 (the vertex) excluded, everything between included.
  return Ray{origin, vertex - origin, std::numeric_limits<float>::denorm_min(), std::nextafter(1.0f, 0.0f)};
}

std::vector<Visibility> compute_visibility(const Accelerator& accel, const TriangleMesh& mesh,
                                           const std::vector<Vec3f>& verts, Vec3f origin) {
  // One segment (ray and filter) per finite vertex, all traced as one batch.
  std::vector<std::size_t> row;
  std::vector<OwnVertex> own;
  std::vector<Ray> rays;
  row.reserve(verts.size());
  own.reserve(verts.size());
  rays.reserve(verts.size());
  for (std::size_t i = 0; i < verts.size(); ++i) {
    if (!is_finite(verts[i])) continue;
    row.push_back(i);
    own.push_back(OwnVertex{&mesh, verts[i]});
    rays.push_back(visibility_ray(origin, verts[i]));
  }
  std::vector<HitFilter> filters(own.size());
  for (std::size_t k = 0; k < own.size(); ++k) filters[k] = HitFilter{&touches_vertex, &own[k]};
  std::vector<uint8_t> occluded(rays.size());
  trace_occluded(accel, rays, occluded, filters.data());

  std::vector<Visibility> result(verts.size(), Visibility::undefined);
  for (std::size_t k = 0; k < row.size(); ++k)
    result[row[k]] = occluded[k] ? Visibility::blocked : Visibility::visible;
  return result;
}

}  // namespace rayvec
