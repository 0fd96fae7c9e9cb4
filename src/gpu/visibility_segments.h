// The visibility workload (accel/visibility.h) as the device traces it: one ray per finite vertex,
// with that vertex as the point whose triangles the any-hit query ignores.
#pragma once
#include <cstddef>
#include <vector>

#include "accel/visibility.h"
#include "math/vec3.h"
#include "rays/ray.h"

namespace rayvec::gpu {

struct VisibilitySegments {
  std::vector<std::size_t> row;  // the vertex row of each ray
  std::vector<Ray> rays;
  std::vector<Vec3f> points;  // the vertex itself: triangles with a corner there never block
};

VisibilitySegments visibility_segments(const std::vector<Vec3f>& verts, Vec3f origin);

// The per-vertex answer from the per-ray occlusion flags (non-finite vertices: undefined).
std::vector<Visibility> visibility_answers(const VisibilitySegments& s, std::size_t vertex_count,
                                           const std::vector<uint8_t>& occluded);

}  // namespace rayvec::gpu
