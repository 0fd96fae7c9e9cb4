// Intersector: which ray–triangle arithmetic a query uses. Every kernel (scalar, AVX2, AVX-512;
// brute force or a BVH leaf) is instantiated once per intersector, so adding one (e.g. watertight)
// means a new enum value and one instantiation per ISA unit — callers only pass the value through.
//
// Range: the float intersectors' products grow as |x|³ (t·det of `mt` and `paper`, T of
// `watertight`, the latter also as 1/|d|); the contracts below hold for vertices and origins
// within ±1e10 and directions whose largest component is in [1e-6, 1e16], which the loaders
// enforce (geometry/coordinate_range.h). Beyond it a product may overflow to Inf: never a NaN or
// a false hit, but a miss where the exact answer is a hit.
#pragma once
#include <optional>
#include <string_view>

namespace rayvec {

enum class Intersector {
  // The arithmetic of Sena et al. (2018), Figure 4, exactly: float Möller–Trumbore (Möller & Trumbore
  // 1997) with f = 1/det, rejecting |det| < 1e-6 and accepting t > 1e-6 (and tmin <= t <= tmax).
  // Kept to reproduce the paper. Contract: none beyond the paper's — the absolute epsilon culls small
  // or distant triangles (a 1e-4-sized triangle has det ~ 1e-8 and is never hit), edges are closed
  // up to float rounding of u = f·(s·h). NaN in a ray or vertex never yields a hit (ordered compares).
  paper,

  // Float Möller–Trumbore without any absolute epsilon: only det = 0 (a ray parallel to the plane, or a
  // zero-area triangle) rejects, so tiny triangles are hit. Division-free barycentric tests with the
  // sign of det folded in: u·|det| >= 0, v·|det| >= 0, (u+v)·|det| <= |det| — closed edges, evaluated
  // in float with FMA in the SIMD kernels, so a ray through a shared edge hits at least one side
  // except for rounding (not guaranteed watertight). Computed over the normal ng = e2 × e1
  // (det = d·ng, t·det = (v0 − o)·ng), stored with the triangles or formed per step by the same
  // float operations (the same bits either way); t = (t·det)/det by one correctly rounded
  // division, accepted when tmin <= t <= tmax, reported without a sign on zero (a hit at t = 0 is
  // +0). Every comparison is ordered: a NaN or Inf-derived NaN anywhere fails it, so NaN input never
  // produces a hit and never produces a NaN output. Degenerate (zero-area) triangles have det = 0
  // and never hit.
  mt,

  // The `mt` contract evaluated in double: float vertices converted exactly, edges computed in double
  // from the vertices (not from float-rounded edges), t rounded to float at the end. About 2^29 times
  // less rounding than `mt`; same NaN and degenerate guarantees; still not watertight. BVH ray packets
  // intersect leaves lane by lane with the single-ray kernel (no packet leaf: a double step holds
  // half the lanes, and no command defaults to it).
  mt64,

  // Watertight ray/triangle intersection (Woop, Benthin & Wald 2013) in float, from the exact input
  // vertices (kernels/watertight.inl). Contract: edges and vertices are closed, and on a closed mesh
  // (triangles sharing vertices by value) a ray that crosses the surface hits at least one of the
  // triangles around any shared edge or vertex it passes through — no ray slips through a crack,
  // whatever the rounding. Rays that only graze the surface (tangent at an edge or vertex) are
  // not covered. Hits are decided on the ray's sheared, translated copy of the triangle, so near
  // an edge the answer may differ from the exact one by float rounding (on the safe side for
  // closed meshes). Accepted when det = U + V + W is nonzero and finite, tmin <= t <= tmax, and t
  // exceeds a bound on its own rounding error (watertight_t_error, after Pharr et al.'s
  // conservative t): a ray leaving a surface from an offset origin never finds it again;
  // degenerate (zero-area) triangles and rays parallel to the plane have det = 0 and never hit.
  // A NaN or Inf in the ray's origin, direction, tmin or tmax, or in a vertex, never yields a hit
  // or a NaN output. No FMA: the same ids and t on every ISA. BVH ray packets run a packet leaf
  // (bvh/watertight_packet_leaf.inl) with the single-ray kernel's results bit for bit.
  watertight,

  // The `watertight` contract evaluated in double (no double fallback needed for zero edge
  // functions: they are taken as on-edge, which keeps watertightness); t rounded to float at the
  // end. Same NaN/degenerate guarantees; same results on every ISA. BVH ray packets intersect leaves
  // lane by lane with the single-ray kernel, as for mt64.
  watertight64,
};

inline constexpr Intersector kAllIntersectors[] = {Intersector::paper, Intersector::mt, Intersector::mt64,
                                                   Intersector::watertight, Intersector::watertight64};

const char* intersector_name(Intersector i);
std::optional<Intersector> parse_intersector(std::string_view name);

}  // namespace rayvec
