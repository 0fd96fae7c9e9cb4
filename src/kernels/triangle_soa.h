// TriangleSoA: triangles as structure-of-arrays, the layout of Sena et al. (2018) — one array per
// coordinate, so W consecutive triangles load as one SIMD register per coordinate.
// Departures from the paper: edges e1 = v1 − v0 and e2 = v2 − v0 are precomputed (the float kernels
// read v0, e1, e2 and the normal ng = e2 × e1); v1 and v2 are kept too so double-precision and (later) watertight kernels
// work from the exact input vertices. Arrays are 64-byte aligned and padded with zero-area triangles
// (id −1) to a multiple of kBlock plus one block of slack, so a kernel may always load a full
// register at any index below count.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace rayvec {

struct TriangleMesh;

// What the ISA kernels see: plain pointers, no member functions (ISA units must not instantiate
// inline code shared with baseline units).
struct TriangleArrays {
  const float *v0x, *v0y, *v0z;
  const float *e1x, *e1y, *e1z;
  const float *e2x, *e2y, *e2z;
  const float *v1x, *v1y, *v1z;
  const float *v2x, *v2y, *v2z;
  // ng = e2 × e1, the unnormalized geometric normal (Embree's orientation), so the float `mt` kernel
  // gets det = d · ng and t·det = (v0 − o) · ng without recomputing a cross product per ray.
  const float *ngx, *ngy, *ngz;
  const int32_t* id;  // triangle id per slot; ids inside any range a kernel is given must increase
  uint32_t count;     // real triangles (slots [count, padded) are zero-area padding)
};

class TriangleSoA {
 public:
  static constexpr uint32_t kBlock = 16;  // widest SIMD width in floats (AVX-512)

  TriangleSoA() = default;
  // Triangles of `mesh` in the given order of triangle ids (all of them in id order when empty).
  explicit TriangleSoA(const TriangleMesh& mesh, std::span<const uint32_t> order = {});

  uint32_t size() const { return count_; }
  uint32_t padded_size() const { return padded_; }
  const TriangleArrays& arrays() const { return arrays_; }
  std::size_t bytes() const;

  // The triangle in slot i (for scalar reference code and tests).
  Vec3f v0(uint32_t i) const { return {arrays_.v0x[i], arrays_.v0y[i], arrays_.v0z[i]}; }
  Vec3f v1(uint32_t i) const { return {arrays_.v1x[i], arrays_.v1y[i], arrays_.v1z[i]}; }
  Vec3f v2(uint32_t i) const { return {arrays_.v2x[i], arrays_.v2y[i], arrays_.v2z[i]}; }
  int32_t id(uint32_t i) const { return arrays_.id[i]; }

 private:
  struct FreeDeleter {
    void operator()(void* p) const { std::free(p); }
  };
  std::unique_ptr<float, FreeDeleter> floats_;
  std::unique_ptr<int32_t, FreeDeleter> ids_;
  TriangleArrays arrays_{};
  uint32_t count_ = 0, padded_ = 0;
};

}  // namespace rayvec
