#include "gpu/visibility_segments.h"

namespace rayvec::gpu {

VisibilitySegments visibility_segments(const std::vector<Vec3f>& verts, Vec3f origin) {
  VisibilitySegments s;
  for (std::size_t i = 0; i < verts.size(); ++i) {
    if (!is_finite(verts[i])) continue;
    s.row.push_back(i);
    s.rays.push_back(visibility_ray(origin, verts[i]));
    s.points.push_back(verts[i]);
  }
  return s;
}

std::vector<Visibility> visibility_answers(const VisibilitySegments& s, std::size_t vertex_count,
                                           const std::vector<uint8_t>& occluded) {
  std::vector<Visibility> result(vertex_count, Visibility::undefined);
  for (std::size_t k = 0; k < s.row.size(); ++k)
    result[s.row[k]] = occluded[k] ? Visibility::blocked : Visibility::visible;
  return result;
}

}  // namespace rayvec::gpu
