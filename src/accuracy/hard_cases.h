// Hard-case families for judging intersectors against the exact oracle: scenes and rays built so that
// rounding decides the answer (rays through shared vertices and edges, far-away and tiny geometry,
// grazing rays, degenerate triangles, non-finite input), plus a random control family. Shared by
// the numerics tests and `rayvec accuracy`; deterministic for a given seed and scale.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rays/ray.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {

struct HardCaseFamily {
  std::string name;
  std::string description;
  TriangleMesh mesh;
  std::vector<Ray> rays;
  // Every ray crosses a closed surface (or the shared interior edge of a surface) transversally, so a
  // watertight intersector must report a hit for every ray the oracle says hits.
  bool crossing = false;
  // Every triangle has zero area: nobody may report a hit.
  bool degenerate = false;
};

// All families. `scale` multiplies the ray counts (1: a few thousand rays in all, for tests).
std::vector<HardCaseFamily> hard_case_families(uint64_t seed, int scale);

// Random triangles and random rays: the control family where rounding rarely matters.
HardCaseFamily random_control_family(uint64_t seed, int scale);

// Building blocks, exposed for tests: a closed icosphere (shared vertices) with 20·4^subdivisions
// triangles, and a closed octahedron, each around `centre`, randomly rotated when rotate_seed != 0.
TriangleMesh make_icosphere(Vec3d centre, double radius, int subdivisions, uint64_t rotate_seed);
TriangleMesh make_octahedron(Vec3d centre, double radius, uint64_t rotate_seed);
// The closed box centre ± half whose faces are n × n grids of axis-aligned squares, two triangles
// each (diagonals alternating), vertices shared: the axis_parallel_grid family's mesh is
// grid_box({0, 0, 0}, 1, 4).
TriangleMesh grid_box(Vec3d centre, double half, int n);

}  // namespace rayvec
