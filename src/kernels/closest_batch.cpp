#include "kernels/closest_batch.h"

#include <algorithm>
#include <vector>

namespace rayvec {

void closest_batch(const TriangleKernels& kernels, const TriangleArrays& tris, uint32_t begin, uint32_t end,
                   const Ray* rays, Hit* hits, std::size_t n) {
  for (uint32_t chunk = begin; chunk < end;) {
    const uint32_t chunk_end = end - chunk > kTriangleChunk ? chunk + kTriangleChunk : end;
    if (kernels.closest_group)  // several rays per triangle load where the table has it
      kernels.closest_group(tris, chunk, chunk_end, rays, hits, n);
    else
      for (std::size_t k = 0; k < n; ++k) kernels.closest(tris, chunk, chunk_end, rays[k], hits[k]);
    chunk = chunk_end;
  }
}

void occluded_batch(const TriangleKernels& kernels, const TriangleArrays& tris, uint32_t begin, uint32_t end,
                    const Ray* rays, uint8_t* occluded, std::size_t n, const HitFilter* filters) {
  thread_local std::vector<uint32_t> open;  // the rays without a hit so far
  open.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    occluded[k] = 0;
    open[k] = uint32_t(k);
  }
  std::size_t open_count = n;
  for (uint32_t chunk = begin; chunk < end && open_count > 0;) {
    const uint32_t chunk_end = end - chunk > kTriangleChunk ? chunk + kTriangleChunk : end;
    std::size_t still = 0;
    if (kernels.occluded_group) {  // several rays per triangle load where the table has it
      for (std::size_t j = 0; j < open_count; j += kMaxOccludedGroup) {
        const int m = int(std::min<std::size_t>(kMaxOccludedGroup, open_count - j));
        uint32_t ids[kMaxOccludedGroup];
        const Ray* group[kMaxOccludedGroup];
        const HitFilter* group_filters[kMaxOccludedGroup];
        for (int q = 0; q < m; ++q) {
          ids[q] = open[j + std::size_t(q)];
          group[q] = &rays[ids[q]];
          group_filters[q] = filters ? &filters[ids[q]] : nullptr;
        }
        const unsigned hit = kernels.occluded_group(tris, chunk, chunk_end, group, group_filters, m);
        for (int q = 0; q < m; ++q) {
          if (hit >> q & 1u)
            occluded[ids[q]] = 1;
          else
            open[still++] = ids[q];
        }
      }
    } else {
      for (std::size_t j = 0; j < open_count; ++j) {
        const uint32_t k = open[j];
        if (kernels.occluded(tris, chunk, chunk_end, rays[k], filters ? &filters[k] : nullptr))
          occluded[k] = 1;
        else
          open[still++] = k;
      }
    }
    open_count = still;
    chunk = chunk_end;
  }
}

}  // namespace rayvec
