#include "kernels/triangle_soa.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>

#include "platform/large_buffer.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

constexpr std::int64_t kParallelFill = 2048;  // fewer slots: fill on the calling thread

// The fill reads the mesh in the tree's slot order: neighbouring slots lie near in space but
// anywhere in the mesh's arrays, so a slot's index row and vertices would be cache misses that
// the hardware prefetchers cannot foresee. They are fetched this many slots ahead: the index row
// first, then, once it has arrived, the vertices it names (benchmarks.md#decision-soa-fill-prefetch).
// Smaller meshes' arrays stay in the caches, where the prefetches only cost.
constexpr std::int64_t kIndexAhead = 64, kVertexAhead = 32;
constexpr std::size_t kPrefetchFrom = std::size_t(1) << 15;  // triangles

}  // namespace

TriangleSoA::TriangleSoA(const TriangleMesh& mesh, std::span<const uint32_t> order, Normals normals) {
  const std::size_t n = order.empty() ? mesh.size() : order.size();
  // slot_offset is 32-bit: every float of the blocks must have an offset below 2^32
  constexpr std::size_t kMaxSlots = (std::size_t(1) << 32) / kSlotRows - 2 * kBlock;
  if (n > kMaxSlots)
    throw std::length_error("too many triangles for TriangleSoA (at most " + std::to_string(kMaxSlots) + ")");
  count_ = static_cast<uint32_t>(n);
  padded_ = padded_slots(count_);  // one block of slack
  // uninitialized: the fill below writes every slot, in parallel, so the pages are first touched
  // by the threads that fill them (a serial memset was a third of the fill's time on 1M triangles)
  blocks_ = allocate_large_buffer(std::size_t(padded_) * kSlotRows * 4);
  if (normals == Normals::stored) normals_ = allocate_large_buffer(std::size_t(padded_) * kNormalBytes);
  float* ng_rows = static_cast<float*>(normals_.get());

  // row k of every block starts kBlock·k 4-byte values into the block; the vertex rows (v0, v2, v1:
  // what the float `mt` kernel reads) first, then the ids. Each row holds one type (the id row
  // only int32, the others only float).
  constexpr uint32_t kV0 = kRowV0, kV2 = kRowV2, kV1 = kRowV1, kId = kRowId;
  float* base = static_cast<float*>(blocks_.get());
  int32_t* ids = reinterpret_cast<int32_t*>(base + std::size_t(kId) * kBlock);

  // every slot written once: triangles below count_, zero-area padding (id −1) above
  const std::int64_t slots = padded_, count = count_;
  const bool fetch_ahead = !order.empty() && mesh.size() >= kPrefetchFrom;
  float bound = 0.0f;
#pragma omp parallel for schedule(static) reduction(max : bound) if (slots >= kParallelFill)
  for (std::int64_t i = 0; i < slots; ++i) {
    float* const slot = base + slot_offset(uint32_t(i));
    // written in the loop: g++ dropped the calls of a helper whose only effects were prefetches
    if (fetch_ahead && i + kIndexAhead < count) {
      const uint32_t ahead = order[std::size_t(i + kIndexAhead)];
      if (ahead != kPaddingSlot) __builtin_prefetch(&mesh.triangles[ahead]);
    }
    if (fetch_ahead && i + kVertexAhead < count) {
      const uint32_t ahead = order[std::size_t(i + kVertexAhead)];
      if (ahead != kPaddingSlot)
        for (const uint32_t v : mesh.triangles[ahead]) __builtin_prefetch(&mesh.positions[v]);
    }
    const uint32_t tri = i < count && !order.empty() ? order[std::size_t(i)] : uint32_t(i);
    int32_t& id = ids[slot_offset(uint32_t(i))];
    if (i >= count || tri == kPaddingSlot) {
      for (uint32_t k = 0; k < kSlotRows; ++k)
        if (k != kId) slot[k * kBlock] = 0.0f;
      id = -1;
      if (ng_rows)
        for (uint32_t a = 0; a < 3; ++a) ng_rows[normal_offset(uint32_t(i)) + a * kBlock] = 0.0f;
      continue;
    }
    const Vec3f p0 = mesh.vertex(tri, 0), p1 = mesh.vertex(tri, 1), p2 = mesh.vertex(tri, 2);
    const Vec3f rows[] = {p0, p2, p1};
    for (const Vec3f& p : rows)
      for (int a = 0; a < 3; ++a) {
        const float m = std::fabs(p[a]);
        bound = m <= bound ? bound : std::isnan(m) ? std::numeric_limits<float>::infinity() : m;
      }
    const int first[] = {kV0, kV2, kV1};
    for (uint32_t r = 0; r < 3; ++r)
      for (uint32_t a = 0; a < 3; ++a) slot[(first[r] + a) * kBlock] = rows[r][int(a)];
    id = static_cast<int32_t>(tri);
    if (ng_rows) {
      // the kernels' mt_normal, in the same float operations: e2 × e1
      const Vec3f ng = cross(p2 - p0, p1 - p0);
      for (uint32_t a = 0; a < 3; ++a) ng_rows[normal_offset(uint32_t(i)) + a * kBlock] = ng[int(a)];
    }
  }
  const auto row = [&](int k) -> const float* { return base + std::size_t(k) * kBlock; };
  arrays_ =
      TriangleArrays{row(kV0),     row(kV0 + 1), row(kV0 + 2), row(kV1), row(kV1 + 1), row(kV1 + 2), row(kV2),
                     row(kV2 + 1), row(kV2 + 2), ids,          ng_rows,  count_,       bound};
}

std::size_t TriangleSoA::bytes() const {
  return bytes_for(count_, stores_normals() ? Normals::stored : Normals::formed);
}

}  // namespace rayvec
