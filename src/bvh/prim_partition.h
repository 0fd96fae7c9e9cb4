// In-place partition of the SAH builder's primitives (bvh/binary_bvh.cpp) by a predicate, returning
// the first primitive of the right side and the centroid bounds of both sides (the children's
// binning needs them, and the partition visits every centroid anyway). `serial` on the calling
// thread; `chunked` for the top of the tree: each of kPartitionChunks chunks partitioned in place as
// an OpenMP task, then the right primitives before the split point trade places with the left ones
// after it, in pieces as tasks — the root's partition was the largest serial step of the build, and
// a second buffer to partition through would cost 32 bytes a triangle of fresh memory. The order
// inside each side does not matter: every later decision depends only on the set of primitives in a
// range. Included only by the builder.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>

#include "bvh/build_prim.h"
#include "bvh/sah_bins.h"
#include "geometry/bbox.h"
#include "platform/attributes.h"
#include "simd/float4_sse.h"

namespace rayvec::prim_partition {

using sah_bins::kInf;

inline constexpr int kPartitionChunks = 4;

// Each primitive is tested once: [begin, i) goes left, [j, end) goes right, and [i, j) is not yet
// tested. The centroid bounds of both sides grow on the way (x86 min/max with the accumulator
// second, so a NaN centroid is ignored as in the builder's range bounds). Inline: called out of line,
// the build read 1.5 % slower.
template <class F>
RAYVEC_INLINE uint32_t serial(BuildPrim* prims, uint32_t begin, uint32_t end, const F& goes_left,
                              BBox (&cbox)[2]) {
  using sse::Float4;
  const Float4 half = Float4::broadcast(0.5f);
  Float4 lo[2] = {Float4::broadcast(kInf), Float4::broadcast(kInf)};
  Float4 hi[2] = {Float4::broadcast(-kInf), Float4::broadcast(-kInf)};
  uint32_t i = begin, j = end;
  while (i < j) {
    BuildPrim& p = prims[i];
    const Float4 c = (Float4::load(p.lo).xyz() + Float4::load(p.hi)) * half;
    const int side = goes_left(p) ? 0 : 1;
    lo[side] = vmin(c, lo[side]);
    hi[side] = vmax(c, hi[side]);
    if (side == 0) {
      ++i;
    } else {
      --j;
      std::swap(p, prims[j]);
    }
  }
  for (int s = 0; s < 2; ++s) {
    float l[4], h[4];
    lo[s].store(l);
    hi[s].store(h);
    cbox[s] = BBox{{l[0], l[1], l[2]}, {h[0], h[1], h[2]}};
  }
  return i;
}

// At most kPartitionChunks runs [begin, end) of primitive positions, read as one sequence.
struct Runs {
  uint32_t begin[kPartitionChunks], end[kPartitionChunks];
  int count = 0;
  void add(uint32_t b, uint32_t e) {
    if (b >= e) return;
    begin[count] = b;
    end[count++] = e;
  }
  uint32_t size() const {
    uint32_t n = 0;
    for (int r = 0; r < count; ++r) n += end[r] - begin[r];
    return n;
  }
  // Walks the positions from the k-th on.
  struct Cursor {
    const Runs* runs;
    int r;
    uint32_t at;
    uint32_t next() {
      while (at == runs->end[r]) at = runs->begin[++r];
      return at++;
    }
  };
  Cursor at(uint32_t k) const {
    int r = 0;
    while (r < count && k >= end[r] - begin[r]) {
      k -= end[r] - begin[r];
      ++r;
    }
    // k == size(): a cursor that is never read
    return r < count ? Cursor{this, r, begin[r] + k} : Cursor{this, 0, 0};
  }
};

// serial()'s result, the chunks and the swaps as tasks of the calling task (call from inside a
// parallel region).
template <class F>
uint32_t chunked(BuildPrim* prims, uint32_t begin, uint32_t end, const F& goes_left, BBox (&cbox)[2]) {
  constexpr int C = kPartitionChunks;
  const uint32_t step = (end - begin + C - 1) / C;
  uint32_t first[C + 1], mid[C];
  BBox sides[C][2];
  for (int c = 0; c <= C; ++c) first[c] = std::min(end, begin + uint32_t(c) * step);
  for (int c = 0; c < C; ++c) {
#pragma omp task shared(first, mid, sides, goes_left) firstprivate(c, prims)
    mid[c] = serial(prims, first[c], first[c + 1], goes_left, sides[c]);
  }
#pragma omp taskwait
  uint32_t split = begin;
  for (int c = 0; c < C; ++c) split += mid[c] - first[c];
  // the misplaced primitives, as runs in order: right ones before `split`, left ones after it (as
  // many of each)
  Runs right_before, left_after;
  for (int c = 0; c < C; ++c) {
    right_before.add(mid[c], std::min(first[c + 1], split));
    left_after.add(std::max(first[c], split), mid[c]);
  }
  const uint32_t misplaced = right_before.size();
  for (int t = 0; t < C; ++t) {
    const auto k0 = uint32_t(uint64_t(misplaced) * uint32_t(t) / C);
    const auto k1 = uint32_t(uint64_t(misplaced) * uint32_t(t + 1) / C);
#pragma omp task shared(right_before, left_after) firstprivate(k0, k1, prims)
    {
      Runs::Cursor a = right_before.at(k0), b = left_after.at(k0);
      for (uint32_t k = k0; k < k1; ++k) std::swap(prims[a.next()], prims[b.next()]);
    }
  }
#pragma omp taskwait
  for (int side = 0; side < 2; ++side) {
    sah_bins::BinBox box;
    for (int c = 0; c < C; ++c)
      for (int a = 0; a < 3; ++a) {
        box.lo[a] = sah_bins::min_keep(box.lo[a], sides[c][side].lo[a]);
        box.hi[a] = sah_bins::max_keep(box.hi[a], sides[c][side].hi[a]);
      }
    cbox[side] = box.box();
  }
  return split;
}

}  // namespace rayvec::prim_partition
