// TriangleKernels: the function table one (ISA, intersector) pair provides. Brute force calls it on the
// whole TriangleSoA, a BVH on each leaf's range; the table is chosen once (triangle_kernels.cpp) and never
// per ray.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "kernels/intersector.h"
#include "platform/isa.h"
#include "kernels/triangle_soa.h"
#include "rays/ray.h"

namespace rayvec {

// Lets an any-hit query ignore some triangles (e.g. the ones touching the vertex whose visibility is
// asked). Called only for triangles that pass the intersection test, so misses cost nothing.
struct HitFilter {
  bool (*ignore)(const void* context, int32_t triangle_id);
  const void* context;
};

// The most rays one TriangleKernels::occluded_group call takes.
inline constexpr int kMaxOccludedGroup = 16;

struct TriangleKernels {
  Isa isa;
  Intersector intersector;
  int width;  // triangles per SIMD step (16 AVX-512, 8 AVX2, 1 scalar; halved for double)

  // Any begin and end <= count are allowed; steps load whole blocks of W slots at multiples of W
  // (blocked rows, triangle_soa.h) and mask the lanes outside [begin, end), so a range starting on
  // a multiple of W (as BVH leaves do) saves the masked head step.

  // Closest hit of `ray` among slots [begin, end): replaces `hit` when a triangle is hit with
  // tmin <= t <= min(tmax, hit.t) and it is nearer than `hit` (equal t: lower id wins). `hit` must be
  // a miss or a previous result for the same ray.
  void (*closest)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit);

  // True as soon as any triangle in [begin, end) is hit with tmin <= t <= tmax (and, with a filter,
  // is not ignored by it). filter may be null.
  bool (*occluded)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray& ray,
                   const HitFilter* filter);

  // Optional (may be null): `closest` for rays[0..n) and hits[0..n), each triangle step loaded once
  // for several rays (two, or a group of four or eight from one origin). Same results as n `closest`
  // calls. Used by closest_batch.
  void (*closest_group)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray* rays, Hit* hits,
                        std::size_t n) = nullptr;

  // Optional (may be null): `occluded` for *rays[0..n) with filters[k] (may be null) for *rays[k],
  // n <= kMaxOccludedGroup, each triangle step loaded once for several rays where they start at one
  // origin. Returns the bits of the occluded rays (bit k: *rays[k]), as n `occluded` calls would.
  // Used by occluded_batch.
  unsigned (*occluded_group)(const TriangleArrays& tris, uint32_t begin, uint32_t end, const Ray* const* rays,
                             const HitFilter* const* filters, int n) = nullptr;
};

// How the float `mt` closest-hit kernels pre-test a step before its exact depth test (mt_float.inl):
// both are conservative and give the same hits, bit for bit; they differ only in speed, which depends
// on how a CPU executes mask instructions (benchmarks.md#decision-sign-pretest).
//   sign_bits         — the five conditions as sign bits, ORed and tested by one mask instruction
//   ordered_compares  — the five conditions as ordered compares chained through the lane mask
enum class MtPretest { sign_bits, ordered_compares };

// The pre-test the `mt` table of `isa` uses by default on a CPU whose cpuid vendor is `vendor`:
// ordered_compares for AVX-512 on GenuineIntel, sign_bits otherwise.
MtPretest default_mt_pretest(Isa isa, std::string_view vendor);
// "sign bits" | "ordered compares" (what `rayvec info` prints).
const char* mt_pretest_name(MtPretest pretest);

// A tuning switch for measuring both pre-tests on one CPU (`bench paper --pretest`): from this call on,
// the tables triangle_kernels(isa, intersector) hands out use `pretest` for every ISA; nullopt restores
// each ISA's default. Set before any accelerator is built (it is not synchronised with tracing).
void set_mt_pretest(std::optional<MtPretest> pretest);
// The pre-test triangle_kernels(isa, intersector) uses for `isa` on this CPU.
MtPretest mt_pretest_in_use(Isa isa);

// The table for an ISA the CPU supports (checked by the caller through isa_supported), with
// mt_pretest_in_use (the running CPU's default_mt_pretest unless set_mt_pretest chose one).
const TriangleKernels& triangle_kernels(Isa isa, Intersector intersector);
// The same with the `mt` pre-test chosen (other intersectors ignore it).
const TriangleKernels& triangle_kernels(Isa isa, Intersector intersector, MtPretest pretest);

// Per-ISA entry points, each defined in its own unit (triangle_kernels_<isa>.cpp).
namespace scalar {
const TriangleKernels& triangle_kernels(Intersector intersector, MtPretest pretest);
}
namespace avx2 {
const TriangleKernels& triangle_kernels(Intersector intersector, MtPretest pretest);
}
namespace avx512 {
const TriangleKernels& triangle_kernels(Intersector intersector, MtPretest pretest);
}

}  // namespace rayvec
