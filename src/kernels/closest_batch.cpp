#include "kernels/closest_batch.h"

namespace rayvec {

void closest_batch(const TriangleKernels& kernels, const TriangleArrays& tris, uint32_t begin, uint32_t end,
                   const Ray* rays, Hit* hits, std::size_t n) {
  for (uint32_t chunk = begin; chunk < end;) {
    const uint32_t chunk_end = end - chunk > kTriangleChunk ? chunk + kTriangleChunk : end;
    std::size_t k = 0;
    if (kernels.closest_pair)  // two rays per triangle load where the table has it
      for (; k + 2 <= n; k += 2) kernels.closest_pair(tris, chunk, chunk_end, rays + k, hits + k);
    for (; k < n; ++k) kernels.closest(tris, chunk, chunk_end, rays[k], hits[k]);
    chunk = chunk_end;
  }
}

}  // namespace rayvec
