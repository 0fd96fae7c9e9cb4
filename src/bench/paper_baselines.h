// The two scalar baselines of Sena, Sampaio, Nascimento & Nery (2018), Table 1: `original` and
// `optimized`, both the Figure 1 loop (every ray against every triangle, edges computed on the fly,
// f = 1/a, |a| < 1e-6 rejected, t > 1e-6 accepted) — they differ only in memory layout:
//   original  — AoS: one array of all triangle vertices (v0, v1, v2 interleaved, 9 floats a triangle)
//               and one of all rays (Ray structs), as the paper's section 5.1 describes it;
//   optimized — SoA: one array per coordinate (v0x[], v0y[], ..., v2z[]), rays as a RayBatch.
// Their arithmetic is the `paper` intersector's, operation for operation (separately rounded multiplies
// and adds, no FMA: the project builds with -std=c++20, which makes g++ default to
// -ffp-contract=off), so they return exactly the ids, t, u and v of the vectorized `paper` kernels.
// Departures from Figure 1, each needed for that exactness: the epsilons are the float 1e-6f the
// vectorized Figure 4 broadcasts (Figure 1 compares against the double 1e-6, which differs from 1e-6f
// in the last bits); rays carry [tmin, tmax] like every rayvec query; ties go to the lowest id
// (Figure 1 keeps the first triangle too, via its strict t < best test). Baseline x86-64 code only.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rays/ray.h"

namespace rayvec {

struct TriangleMesh;

// Original layout: triangle i's vertices at xyz[9i .. 9i+8] = v0.xyz, v1.xyz, v2.xyz.
struct PaperAosTriangles {
  std::vector<float> xyz;
  std::size_t size() const { return xyz.size() / 9; }
};

// Optimized layout: one array per vertex coordinate.
struct PaperSoaTriangles {
  std::vector<float> v0x, v0y, v0z, v1x, v1y, v1z, v2x, v2y, v2z;
  std::size_t size() const { return v0x.size(); }
};

PaperAosTriangles paper_aos_triangles(const TriangleMesh& mesh);
PaperSoaTriangles paper_soa_triangles(const TriangleMesh& mesh);

// Closest hit of rays [begin, end) over every triangle (triangle id = index), written to
// hits[begin, end): nearest t with t > 1e-6 and tmin <= t <= tmax; equal t: lowest id; a miss is
// {tri = -1, t = inf}. Single-threaded; callers split ray ranges across threads.
void closest_original(const PaperAosTriangles& tris, std::span<const Ray> rays, std::size_t begin,
                      std::size_t end, std::span<Hit> hits);
void closest_optimized(const PaperSoaTriangles& tris, const RayBatch& rays, std::size_t begin,
                       std::size_t end, std::span<Hit> hits);

}  // namespace rayvec
