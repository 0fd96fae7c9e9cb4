// Vertex visibility, the workload of the CUDA study (Gallina 2023) with correct semantics: is the open
// segment from an origin to each vertex free of triangles? The study tested every triangle with
// epsilons (|det| < 1e-5, 1e-5 margins on u and v, t <= 1 + 1e-5), so a vertex's own triangles and
// triangles behind the vertex could block it; here the segment is open at both ends and the triangles
// having a corner at the vertex's position are ignored through the any-hit filter.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "accel/accelerator.h"
#include "math/vec3.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {

enum class Visibility : uint8_t {
  blocked = 0,    // some triangle crosses the open segment origin -> vertex
  visible = 1,    // none does (also for a vertex at the origin: an empty segment)
  undefined = 2,  // the vertex has a non-finite coordinate
};

// The triangles of `faces` whose three corners are finite, in order (triangle id = position among
// the kept faces). `dropped` counts the faces left out because a corner is not finite.
struct VisibilityMesh {
  TriangleMesh mesh;
  std::size_t dropped = 0;
};
VisibilityMesh build_visibility_mesh(const std::vector<Vec3f>& verts,
                                     const std::vector<std::array<uint32_t, 3>>& faces);

// The segment origin -> vertex as a ray: origin + t·(vertex − origin) for t in [smallest positive
// float, largest float below 1] (open at both ends).
Ray visibility_ray(Vec3f origin, Vec3f vertex);

// Per vertex: the answer for the segment origin -> verts[i], traced as the ray
// origin + t·(verts[i] − origin) with t in [smallest positive float, largest float below 1], and
// triangles with a corner exactly at verts[i] ignored (this covers duplicated vertex positions).
// `accel` must have been built on `mesh`. One trace_occluded batch (OpenMP-parallel, stream path).
std::vector<Visibility> compute_visibility(const Accelerator& accel, const TriangleMesh& mesh,
                                           const std::vector<Vec3f>& verts, Vec3f origin);

}  // namespace rayvec
