// TriangleSoA: triangles as structure-of-arrays, the layout of Sena et al. (2018) — one row per
// coordinate, so W consecutive triangles load as one SIMD register per coordinate.
// Departures from the paper:
// - the exact vertices v0, v1, v2 are stored, not the edges: the kernels form e1 = v1 − v0 and
//   e2 = v2 − v0 with one subtraction each, the very float operation the fill would do, so every
//   kernel sees the same edges bit for bit, while the double-precision and watertight kernels keep
//   the exact input vertices (benchmarks.md#decision-vertices-not-edges);
// - the rows are blocked (AoSoA): slots come in blocks of kBlock = 16, and a block stores its 10
//   rows of 16 slots one after the other (64 bytes a row): the 9 vertex rows first (v0, v2, v1),
//   then the triangle ids (read for every hit: beside the rows, not in a separate array whose line
//   is one more cache miss per hit leaf). A BVH leaf is then one contiguous run of memory instead
//   of a piece of each of 9 arrays megabytes apart (benchmarks.md#decision-blocked-rows). Slot i
//   of row pointer p is p[slot_offset(i)]; a SIMD step loads W lanes from a slot that is a
//   multiple of W (W divides kBlock), so it never crosses a block;
// - the unnormalized normal ng = e2 × e1 of the float `mt` kernels is stored in a second blocked
//   buffer (3 rows a block, 12 bytes a slot) or, with Normals::formed, not at all: the kernels then
//   form it per step from the edges, with the operations of the fill, so the hits are bit for bit
//   the same; a BVH drops it on large meshes and where its triangles would pass 64 bytes each
//   (benchmarks.md#decision-normal-budget).
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
inline constexpr uint32_t kSlotRows = 10;   // 4-byte rows per block
inline constexpr uint32_t kSlotBlockFloats = kSlotBlock * kSlotRows;
// The rows the float `mt` kernels read (v0, v2, v1) are rows 0..kMtRows−1 of a block, v0x first,
// so a block's hot part is the kMtRows·64 bytes from its slot-0 v0x.
inline constexpr uint32_t kMtRows = 9;
// The first row of each vector in a block: row k holds kSlotBlock values and starts kSlotBlock·k
// values after the block's v0x row.
inline constexpr uint32_t kRowV0 = 0, kRowV2 = 3, kRowV1 = 6, kRowId = 9;

// Where slot i of a row lives, relative to that row's pointer in TriangleArrays. Internal linkage
// (static): ISA units and baseline units each keep their own copy.
static constexpr uint32_t slot_offset(uint32_t i) {
  return i / kSlotBlock * kSlotBlockFloats + i % kSlotBlock;
}
// Where slot i's normal x lies in TriangleArrays::ng (y and z kSlotBlock and 2·kSlotBlock after).
static constexpr uint32_t normal_offset(uint32_t i) {
  return i / kSlotBlock * (3 * kSlotBlock) + i % kSlotBlock;
}

// What the ISA kernels see: plain pointers, no member functions (ISA units must not instantiate
// inline code shared with baseline units). Every row, ids included, is read at slot_offset(i).
// The rows are those of one blocked buffer, so row k of slot i is also at
// v0x + slot_offset(i) + kSlotBlock·k (kRowV0 …): the float `mt` kernels address all nine rows
// from that one pointer instead of loading nine row pointers per step.
struct TriangleArrays {
  const float *v0x, *v0y, *v0z;
  const float *v1x, *v1y, *v1z;
  const float *v2x, *v2y, *v2z;
  // triangle id per slot (−1: padding); the ids of the triangles in any range a kernel is given
  // must increase
  const int32_t* id;
  // ng = e2 × e1 (Embree's orientation), slot i's x at ng[normal_offset(i)], y and z kSlotBlock and
  // 2·kSlotBlock after it; null when not stored (the float `mt` kernels then form it per step)
  const float* ng;
  uint32_t count;  // slots in use (BVH padding slots included); [count, padded) is zero-area padding
  // no vertex coordinate of any slot exceeds this in magnitude; +inf where unknown or where a
  // coordinate is not finite (the kernels whose products it bounds then take their general path)
  float coord_bound = __builtin_inff();
};

// Whether a TriangleSoA stores the normals ng (12 bytes a slot more) or leaves the kernels to
// form them (the BVH on large meshes and over its memory budget: bvh_normals in bvh_accelerator.h).
enum class Normals { stored, formed };

class TriangleSoA {
 public:
  static constexpr uint32_t kBlock = kSlotBlock;  // widest SIMD width in floats (AVX-512)
  // Bytes a slot takes: its block rows, and its normal when stored.
  static constexpr std::size_t kSlotBytes = kSlotRows * 4, kNormalBytes = 3 * 4;

  TriangleSoA() = default;
  // Triangles of `mesh` in the given order of triangle ids (all of them in id order when empty);
  // an entry kPaddingSlot in `order` makes a zero-area slot with id −1 (BVH leaves use it to keep
  // to the fewest SIMD steps; no kernel reports such a slot).
  static constexpr uint32_t kPaddingSlot = 0xffffffffu;
  explicit TriangleSoA(const TriangleMesh& mesh, std::span<const uint32_t> order = {},
                       Normals normals = Normals::stored);
  // The slots a TriangleSoA of `count` slots allocates (padding and slack included), and the bytes
  // it holds for them.
  static uint32_t padded_slots(uint32_t count) { return (count + kBlock - 1) / kBlock * kBlock + kBlock; }
  static std::size_t bytes_for(uint32_t count, Normals normals) {
    return std::size_t(padded_slots(count)) * (kSlotBytes + (normals == Normals::stored ? kNormalBytes : 0));
  }

  uint32_t size() const { return count_; }
  uint32_t padded_size() const { return padded_; }
  const TriangleArrays& arrays() const { return arrays_; }
  std::size_t bytes() const;
  bool stores_normals() const { return arrays_.ng != nullptr; }

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

  LargeBuffer blocks_, normals_;
  TriangleArrays arrays_{};
  uint32_t count_ = 0, padded_ = 0;
};

}  // namespace rayvec
