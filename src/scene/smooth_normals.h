// smooth_normals: shading normals for the triangles of a smoothing group (OBJ `s N`) whose file gives
// none, so that a model exported with smoothing groups but without `vn` lines renders smooth, as it
// did in the program that made it. The normal at a corner is the mean of the unit normals of the
// group's triangles around that vertex, each weighted by its angle there (Thürmer & Wüthrich 1998):
// unlike a mean weighted by area or by count, it does not change when a face is cut into more
// triangles (see benchmarks.md#decision-smooth-normals). Vertices are shared by index, as OBJ writes
// them; groups meet at a crease.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace rayvec {

inline constexpr uint32_t kNoSmoothNormal = 0xffffffffu;

struct SmoothedNormals {
  std::vector<Vec3f> normals;  // unit vectors (an entry no corner refers to may be 0)
  // Per entry of `wanted`, in its order: each corner's index into `normals`, or kNoSmoothNormal at
  // every corner where the triangle stays flat — a corner whose neighbours' normals cancel (a fold
  // back onto itself), or a triangle of group 0.
  std::vector<std::array<uint32_t, 3>> corners;
};

// The smooth normals of the triangles `wanted` (indices into `triangles`). group[t] is triangle t's
// smoothing group, 0 for none; every triangle of a group contributes at its vertices, wanted or
// not. Computed in double: the normals of tiny triangles and of triangles far from the origin are
// as accurate as those of unit ones, and a triangle without area (or with non-finite corners)
// contributes nothing. The normal's side follows the triangle's winding (right-handed).
SmoothedNormals smooth_normals(std::span<const Vec3f> positions,
                               std::span<const std::array<uint32_t, 3>> triangles,
                               std::span<const uint32_t> group, std::span<const uint32_t> wanted);

}  // namespace rayvec
