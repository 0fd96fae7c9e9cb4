#include "kernels/triangle_soa.h"

#include <cstdint>
#include <new>
#include <stdexcept>

#include "scene/mesh.h"

namespace rayvec {
namespace {

constexpr int kFloatArrays = 18;

constexpr std::int64_t kParallelFill = 16384;  // fewer slots: fill on the calling thread

// Uninitialized: the fill below writes every slot, in parallel, so the pages are first touched by
// the threads that fill them (a serial memset was a third of the fill's time on 1M triangles).
template <typename T>
T* aligned_uninitialized(std::size_t n) {
  const std::size_t bytes = ((n * sizeof(T) + 63) / 64) * 64;
  void* p = std::aligned_alloc(64, bytes == 0 ? 64 : bytes);
  if (!p) throw std::bad_alloc();
  return static_cast<T*>(p);
}

}  // namespace

TriangleSoA::TriangleSoA(const TriangleMesh& mesh, std::span<const uint32_t> order) {
  const std::size_t n = order.empty() ? mesh.size() : order.size();
  if (n > (1u << 31) - 2 * kBlock) throw std::length_error("too many triangles for TriangleSoA");
  count_ = static_cast<uint32_t>(n);
  padded_ = (count_ + kBlock - 1) / kBlock * kBlock + kBlock;  // one block of slack
  floats_.reset(aligned_uninitialized<float>(std::size_t(padded_) * kFloatArrays));
  ids_.reset(aligned_uninitialized<int32_t>(padded_));

  float* base = floats_.get();
  float* a[kFloatArrays];
  for (int k = 0; k < kFloatArrays; ++k) a[k] = base + std::size_t(k) * padded_;
  int32_t* ids = ids_.get();

  // every slot written once: triangles below count_, zero-area padding (id −1) above
  const std::int64_t slots = padded_, count = count_;
#pragma omp parallel for schedule(static) if (slots >= kParallelFill)
  for (std::int64_t i = 0; i < slots; ++i) {
    if (i >= count) {
      for (int k = 0; k < kFloatArrays; ++k) a[k][i] = 0.0f;
      ids[i] = -1;
      continue;
    }
    const uint32_t tri = order.empty() ? uint32_t(i) : order[std::size_t(i)];
    const Vec3f p0 = mesh.vertex(tri, 0), p1 = mesh.vertex(tri, 1), p2 = mesh.vertex(tri, 2);
    const Vec3f e1 = p1 - p0, e2 = p2 - p0, ng = cross(e2, e1);
    const float values[kFloatArrays] = {p0.x, p0.y, p0.z, e1.x, e1.y, e1.z, e2.x, e2.y, e2.z,
                                        p1.x, p1.y, p1.z, p2.x, p2.y, p2.z, ng.x, ng.y, ng.z};
    for (int k = 0; k < kFloatArrays; ++k) a[k][i] = values[k];
    ids[i] = static_cast<int32_t>(tri);
  }
  arrays_ = TriangleArrays{a[0],  a[1],  a[2],  a[3],  a[4],  a[5],  a[6],  a[7],  a[8],  a[9],
                           a[10], a[11], a[12], a[13], a[14], a[15], a[16], a[17], ids, count_};
}

std::size_t TriangleSoA::bytes() const {
  return std::size_t(padded_) * (kFloatArrays * sizeof(float) + sizeof(int32_t));
}

}  // namespace rayvec
