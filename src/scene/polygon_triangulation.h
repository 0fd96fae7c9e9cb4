// How an OBJ face of n corners becomes n − 2 triangles: one rule for both OBJ readers (the fast
// reader and tinyobjloader's, which is asked not to triangulate), so a polygon loses no area
// however it is shaped. tinyobjloader's own ear clipping drops parts of concave polygons (of
// assimp's concave_polygon.obj, 66 corners, it kept 44 of 64 triangles) and covers the wrong side
// of a concave quad.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace rayvec {

// Whether the quad q[0..3] is split along the diagonal 0–2 (triangles 0 1 2 and 0 2 3) rather
// than 1–3 (0 1 3 and 1 2 3). A concave quad (one reflex corner, measured against its Newell
// normal) is split along the diagonal from that corner, the only one inside it; any other quad
// along the shorter diagonal, 0–2 only when strictly shorter in float arithmetic (tinyobjloader's
// rule, so convex quads keep the triangles they always had).
bool quad_splits_at_0_2(const std::array<Vec3f, 4>& q);

// Appends to `out` the n − 2 triangles (triples of corner positions 0..n−1, n = p.size() >= 3) of
// the polygon p: a triangle for 3 corners, quad_splits_at_0_2 for 4, ear clipping for more.
// Contract: every triangle keeps the polygon's corner order (so its winding, hence its geometric
// normal, faces the polygon's side); for a simple polygon — concave, with collinear runs, or with
// a hole joined by a doubled bridge edge — the triangles cover it exactly, without overlap; a
// polygon that crosses itself, or whose corners all lie on a line (zero Newell normal), still
// gives n − 2 triangles over its corners (a fan where nothing better is defined), so no corner is
// dropped. Non-planar polygons are clipped in the plane of their Newell normal. Deterministic:
// the same corners always give the same triangles.
void triangulate_polygon(std::span<const Vec3f> p, std::vector<std::array<uint32_t, 3>>& out);

}  // namespace rayvec
