// The brute-force CUDA kernels, one thread per ray, each over the intersector math `Math`
// (mt_math.h, watertight_math.h) and the loops of trace_loops.h — the code the Cuda* host tests run.
//   global_kernel  — Gallina (2023), first kernel: every thread reads every triangle record from
//                    global memory. Departures: records of 12 floats (vertices and normal) instead
//                    of 9 doubles, any-hit leaves at the first blocking triangle.
//   tiled_kernel   — Gallina (2023), second kernel (Soa = false): the block loads a tile of records
//                    into shared memory, each thread its own records (the study's struct copy), then
//                    every thread tests the tile. Departures: the tile size is a launch parameter;
//                    the last tile is cut at the triangle count (the study read past it); any-hit
//                    blocks stop as soon as all their threads have an answer (__syncthreads_and).
//                    Soa = true is rayvec's layout: rows of one coordinate, loaded row by row so
//                    that neighbouring threads read neighbouring floats (coalesced).
// Included by cuda_backend.cu only.
#pragma once
#include "gpu/trace_loops.h"

namespace rayvec::gpu {

inline constexpr int kThreadsPerBlock = 256;  // the study's block size

struct KernelArgs {
  const float* aos;  // count records of kTriangleRows floats
  const float* soa;  // kTriangleRows rows of row_length floats
  uint32_t count, row_length;
  const GpuRay* rays;
  const float* ignore;  // null, or 3 floats per ray (the visibility filter's point)
  uint32_t ray_count;
  uint32_t tile;      // triangles per shared tile
  uint8_t* occluded;  // any-hit output
  GpuHit* hits;       // closest-hit output
};

struct RecordAt {
  const float* base;
  RAYVEC_HD TriangleView operator()(uint32_t i) const { return {base + i * kTriangleRows, 1}; }
};
struct RowAt {
  const float* base;
  uint32_t stride;
  RAYVEC_HD TriangleView operator()(uint32_t i) const { return {base + i, stride}; }
};

template <class Math, bool AnyHit>
__global__ void __launch_bounds__(kThreadsPerBlock) global_kernel(KernelArgs a) {
  const uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= a.ray_count) return;
  const GpuRay g = a.rays[k];
  const typename Math::Ray r = Math::prepare(g);
  const RecordAt at{a.aos};
  if constexpr (AnyHit) {
    const float* ignore = a.ignore ? a.ignore + 3 * std::size_t(k) : nullptr;
    a.occluded[k] = r.valid && occluded_range<Math>(r, occluded_limit<Math>(g), at, 0, a.count, ignore);
  } else {
    ClosestState<Math> best = closest_start<Math>(g);
    if (r.valid) closest_range<Math>(r, at, 0, a.count, 0, best);
    a.hits[k] = closest_finish<Math>(best);
  }
}

template <class Math, bool AnyHit, bool Soa>
__global__ void __launch_bounds__(kThreadsPerBlock) tiled_kernel(KernelArgs a) {
  extern __shared__ float tile[];  // a.tile triangles: records, or kTriangleRows rows of a.tile
  const uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  const bool active = k < a.ray_count;
  const GpuRay g = active ? a.rays[k] : GpuRay{0, 0, 0, 0, 0, 0, 0, 0};
  const typename Math::Ray r = Math::prepare(g);
  float point[3] = {0, 0, 0};
  if (active && a.ignore)
    for (int c = 0; c < 3; ++c) point[c] = a.ignore[3 * std::size_t(k) + c];
  const float* ignore = a.ignore ? point : nullptr;
  const typename Math::Real tlimit = occluded_limit<Math>(g);
  ClosestState<Math> best = closest_start<Math>(g);
  bool done = !active || !r.valid, occluded = false;
  for (uint32_t base = 0; base < a.count; base += a.tile) {
    const uint32_t n = a.count - base < a.tile ? a.count - base : a.tile;
    // load the tile cooperatively
    if constexpr (Soa) {
      for (uint32_t row = 0; row < kTriangleRows; ++row)
        for (uint32_t j = threadIdx.x; j < n; j += blockDim.x)
          tile[row * a.tile + j] = a.soa[std::size_t(row) * a.row_length + base + j];
    } else {
      for (uint32_t j = threadIdx.x; j < n; j += blockDim.x)
        for (uint32_t row = 0; row < kTriangleRows; ++row)
          tile[j * kTriangleRows + row] = a.aos[(std::size_t(base) + j) * kTriangleRows + row];
    }
    __syncthreads();
    if (!done) {
      if constexpr (AnyHit) {
        if constexpr (Soa)
          occluded = occluded_range<Math>(r, tlimit, RowAt{tile, a.tile}, 0, n, ignore);
        else
          occluded = occluded_range<Math>(r, tlimit, RecordAt{tile}, 0, n, ignore);
        done = occluded;
      } else if constexpr (Soa) {
        closest_range<Math>(r, RowAt{tile, a.tile}, 0, n, int32_t(base), best);
      } else {
        closest_range<Math>(r, RecordAt{tile}, 0, n, int32_t(base), best);
      }
    }
    // the tile is reloaded after this barrier; any-hit blocks leave once every thread has its answer
    if constexpr (AnyHit) {
      if (__syncthreads_and(done)) break;
    } else {
      __syncthreads();
    }
  }
  if (!active) return;
  if constexpr (AnyHit)
    a.occluded[k] = occluded;
  else
    a.hits[k] = closest_finish<Math>(best);
}

}  // namespace rayvec::gpu
