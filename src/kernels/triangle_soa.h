// TriangleSoA: triangles as structure-of-arrays, the layout of Sena et al. (2018) — one row per
// coordinate, so W consecutive triangles load as one SIMD register per coordinate.
// Departures from the paper:
// - the exact vertices v0, v1, v2 and the normal ng = e2 × e1 (e1 = v1 − v0, e2 = v2 − v0) are
//   stored, not the edges: the kernels form e1 and e2 with one subtraction each, the very float
//   operation the fill would do, so every kernel sees the same edges bit for bit, while the
//   double-precision and watertight kernels keep the exact input vertices. 13 rows (52 bytes a slot)
//   instead of 19 with stored edges (benchmarks.md#decision-vertices-not-edges);
// - the rows are blocked (AoSoA): slots come in blocks of kBlock = 16, and a block stores all 13
//   rows of its 16 slots one after the other (64 bytes a row): the 12 rows of the float `mt`
//   kernel first (v0, ng, v2, v1), then the triangle ids (read for every hit: beside the rows, not
//   in a separate array whose line is one more cache miss per hit leaf). A BVH leaf is then one
//   contiguous run of memory instead of a piece of each of 12 arrays megabytes apart
//   (benchmarks.md#decision-blocked-rows). Slot i of row pointer p is
//   p[slot_offset(i)]; a SIMD step loads W lanes from a slot that is a multiple of W (W divides
//   kBlock), so it never crosses a block.
// Rows are 64-byte aligned; the slots are padded with zero-area triangles (id −1) to a multiple of
// kBlock plus one block of slack, so a kernel may always load a full register at any aligned slot
// below count.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <vector>

#include "platform/large_buffer.h"
#include "math/vec3.h"

namespace rayvec {

struct TriangleMesh;

inline constexpr uint32_t kSlotBlock = 16;  // slots per block
inline constexpr uint32_t kSlotRows = 13;   // 4-byte rows per block
inline constexpr uint32_t kSlotBlockFloats = kSlotBlock * kSlotRows;
// The rows the float `mt` kernels read (v0, ng, v2, v1) are rows 0..kMtRows−1 of a block, v0x first,
// so a block's hot part is the kMtRows·64 bytes from its slot-0 v0x.
inline constexpr uint32_t kMtRows = 12;
// The first row of each vector in a block: row k holds kSlotBlock values and starts kSlotBlock·k
// values after the block's v0x row.
inline constexpr uint32_t kRowV0 = 0, kRowNg = 3, kRowV2 = 6, kRowV1 = 9, kRowId = 12;

// Where slot i of a row lives, relative to that row's pointer in TriangleArrays. Internal linkage
// (static): ISA units and baseline units each keep their own copy.
static constexpr uint32_t slot_offset(uint32_t i) {
  return i / kSlotBlock * kSlotBlockFloats + i % kSlotBlock;
}

// What the ISA kernels see: plain pointers, no member functions (ISA units must not instantiate
// inline code shared with baseline units). Every row, ids included, is read at slot_offset(i).
// The rows are those of one blocked buffer, so row k of slot i is also at
// v0x + slot_offset(i) + kSlotBlock·k (kRowV0 …): the float `mt` kernels address all twelve rows
// from that one pointer instead of loading twelve row pointers per step.
struct TriangleArrays {
  const float *v0x, *v0y, *v0z;
  const float *v1x, *v1y, *v1z;
  const float *v2x, *v2y, *v2z;
  // ng = e2 × e1, the unnormalized geometric normal (Embree's orientation), so the float `mt` kernel
  // gets det = d · ng and t·det = (v0 − o) · ng without recomputing a cross product per ray.
  const float *ngx, *ngy, *ngz;
  // triangle id per slot (−1: padding); the ids of the triangles in any range a kernel is given
  // must increase
  const int32_t* id;
  uint32_t count;  // slots in use (BVH padding slots included); [count, padded) is zero-area padding
};

class TriangleSoA {
 public:
  static constexpr uint32_t kBlock = kSlotBlock;  // widest SIMD width in floats (AVX-512)

  TriangleSoA() = default;
  // Triangles of `mesh` in the given order of triangle ids (all of them in id order when empty);
  // an entry kPaddingSlot in `order` makes a zero-area slot with id −1 (BVH leaves use it to keep
  // to the fewest SIMD steps; no kernel reports such a slot).
  static constexpr uint32_t kPaddingSlot = 0xffffffffu;
  explicit TriangleSoA(const TriangleMesh& mesh, std::span<const uint32_t> order = {});

  uint32_t size() const { return count_; }
  uint32_t padded_size() const { return padded_; }
  const TriangleArrays& arrays() const { return arrays_; }
  std::size_t bytes() const;

  // The triangle in slot i (for scalar reference code and tests).
  Vec3f v0(uint32_t i) const { return row3(arrays_.v0x, arrays_.v0y, arrays_.v0z, i); }
  Vec3f v1(uint32_t i) const { return row3(arrays_.v1x, arrays_.v1y, arrays_.v1z, i); }
  Vec3f v2(uint32_t i) const { return row3(arrays_.v2x, arrays_.v2y, arrays_.v2z, i); }
  int32_t id(uint32_t i) const { return arrays_.id[slot_offset(i)]; }

 private:
  static Vec3f row3(const float* x, const float* y, const float* z, uint32_t i) {
    const uint32_t k = slot_offset(i);
    return {x[k], y[k], z[k]};
  }

  LargeBuffer blocks_;
  TriangleArrays arrays_{};
  uint32_t count_ = 0, padded_ = 0;
};

}  // namespace rayvec
