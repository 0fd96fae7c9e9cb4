// The scenes the kernel equivalence tests share, each a mesh and its rays: random unit-cube
// triangles, a closed sphere, a grid aimed at its own edges, and the `mt` pre-tests' hard cases;
// and one closest call per ray, the reference every batched or vectorized path is held to.
#pragma once
#include <vector>

#include "bench/paper_scene.h"
#include "geometry/triangle_mesh.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec::test {

struct KernelScene {
  const char* name;
  TriangleMesh mesh;
  std::vector<Ray> rays;
  bool edge_aimed = false;  // rays aimed exactly at shared edges: edge cases are not rare
};

// A point of the cube [lo, hi)³, and a direction of length 0.1 to 1 (uniform over that shell).
Vec3f random_point(SplitMix64& rng, float lo, float hi);
Vec3f random_direction(SplitMix64& rng);

// 400 random unit-cube triangles (plus a tiny and a degenerate one), random rays with some
// [tmin, tmax] windows, and a camera's rays.
KernelScene random_scene();
// A closed UV sphere (every edge shared by two triangles): rays from inside in random directions,
// and from outside towards random points inside.
KernelScene sphere_scene();
// A 16×16 grid of quads in the plane z = 0.5, rays from above aimed at its grid lines and diagonals.
KernelScene grid_scene();
// Hard cases for the `mt` pre-tests: one triangle three times (ties across lanes and steps: the
// lowest id wins), degenerate ones, a triangle whose plane holds a ray, among random filler; rays at
// vertices and edges, with tmin or tmax exactly at a hit, in a plane, with NaN and zero parts.
KernelScene hard_scene();

// One `closest` call of `k` per ray over every triangle of `soa`.
std::vector<Hit> closest_one_by_one(const TriangleKernels& k, const TriangleSoA& soa,
                                    const std::vector<Ray>& rays);

}  // namespace rayvec::test
