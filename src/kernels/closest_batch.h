// closest_batch (and occluded_batch): the closest hits of many rays over one triangle range, cache-blocked.
// Brute force over a large mesh streams every triangle from L3 or memory once per ray (50,000 triangles
// are 2.4 MB of v0, e1, e2 and ng, more than a typical 1–2 MB L2 per core), so a lone ray is bound by memory
// bandwidth, not arithmetic. Here the range is cut into chunks of kTriangleChunk triangles (8192 × 12 floats
// = 384 KB, resident in such an L2) and every ray of the batch runs through a chunk before the next chunk is
// loaded — the batch shares each load, as a ray packet would, while each ray keeps its own kernel call (one
// ray against W triangles per SIMD step, Sena et al. 2018); where the table has closest_group, several rays
// share each step's loads (benchmarks.md#decision-rays-per-triangle-load). Baseline code: it calls the ISA
// kernels only through the table.
#pragma once
#include <cstdint>

#include "kernels/triangle_kernels.h"

namespace rayvec {

// Triangles per chunk: a multiple of every SIMD width, so the kernels' steps stay aligned. L2- rather
// than L1-sized: each kernel call pays a fixed cost (ray set-up, spilling and reloading its
// constants, the final lane reduction — about 160 cycles for a pair of rays, 1.7 cycles per 16-test
// step at 768 triangles), while the hardware prefetchers keep the loop fed from L2. Larger chunks
// gain until a chunk no longer stays in L2; 8192 leaves room in a 512 KB L2
// (benchmarks.md#decision-triangle-chunk).
inline constexpr uint32_t kTriangleChunk = 8192;

// For k in [0, n): hits[k] becomes the closest hit of rays[k] among slots [begin, end), exactly as
// kernels.closest would return it (each hits[k] must be a miss or a previous result for that ray;
// chunks go in increasing slot order, so ties still go to the lowest id).
void closest_batch(const TriangleKernels& kernels, const TriangleArrays& tris, uint32_t begin, uint32_t end,
                   const Ray* rays, Hit* hits, std::size_t n);

// The any-hit form, tiled the same way: occluded[k] becomes 1 when kernels.occluded over slots
// [begin, end) is true for rays[k] (with filters[k] when `filters` is not null), else 0. A ray
// leaves the batch at its first hit, so later chunks are tested only for the rays still open.
void occluded_batch(const TriangleKernels& kernels, const TriangleArrays& tris, uint32_t begin, uint32_t end,
                    const Ray* rays, uint8_t* occluded, std::size_t n, const HitFilter* filters);

}  // namespace rayvec
