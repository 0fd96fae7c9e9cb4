// The binned SAH builder's bins (bvh/binary_bvh.cpp): a bin's box and count, the bins of all three
// axes over a range of primitives in 4-lane form, the cheapest split, and the bin of a centroid.
// Internal to the builder; the same arithmetic as its 4-lane binning, so both agree on every bin.
#pragma once
#include <bit>
#include <cstdint>
#include <limits>

#include "bvh/build_prim.h"
#include "geometry/bbox.h"
#include "simd/float4_sse.h"

namespace rayvec::sah_bins {

inline constexpr int kMaxBins = 64;
inline constexpr float kInf = std::numeric_limits<float>::infinity();

// min/max that keep the first operand when the second is NaN (a NaN vertex never widens a box);
// branch-free (minss/maxss).
inline float min_keep(float a, float b) { return b < a ? b : a; }
inline float max_keep(float a, float b) { return b > a ? b : a; }

struct BinBox {
  float lo[3] = {kInf, kInf, kInf};
  float hi[3] = {-kInf, -kInf, -kInf};
  uint32_t count = 0;
  void grow(const BuildPrim& p) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = min_keep(lo[a], p.lo[a]);
      hi[a] = max_keep(hi[a], p.hi[a]);
    }
    ++count;
  }
  void grow(const BinBox& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = min_keep(lo[a], b.lo[a]);
      hi[a] = max_keep(hi[a], b.hi[a]);
    }
    count += b.count;
  }
  BBox box() const { return BBox{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
  float half_area() const { return box().half_area(); }
};

// Bins of all three axes over one range of primitives: each bin's box as lo[4], hi[4] (lane 3
// unused) so a primitive grows it with one 4-lane min and max, and its primitive count.
struct Bins {
  alignas(16) float box[3][kMaxBins][8];
  uint32_t count[3][kMaxBins];
  // empties the first `bins` bins of each axis (the others are never read)
  void clear(int bins) {
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < bins; ++k) {
        sse::Float4::broadcast(kInf).store(box[a][k]);
        sse::Float4::broadcast(-kInf).store(box[a][k] + 4);
        count[a][k] = 0;
      }
  }
  BinBox at(int a, int k) const {
    const float* b = box[a][k];
    BinBox r;
    for (int i = 0; i < 3; ++i) {
      r.lo[i] = b[i];
      r.hi[i] = b[4 + i];
    }
    r.count = count[a][k];
    return r;
  }
  void grow(const Bins& o, int bins) {
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < bins; ++k) {
        float* b = box[a][k];
        sse::vmin(sse::Float4::load(o.box[a][k]), sse::Float4::load(b)).store(b);
        sse::vmax(sse::Float4::load(o.box[a][k] + 4), sse::Float4::load(b + 4)).store(b + 4);
        count[a][k] += o.count[a][k];
      }
  }
};

// A box grown bin by bin in the SAH sweeps, in the bins' 4-lane form, and the primitives in those
// bins: the same bounds and areas as BinBox's, a bin in two operations. Lane 3 is 0 in every
// occupied bin (the binning masks the ids out), so the area's arithmetic never meets a denormal.
struct SweepBox {
  sse::Float4 lo = sse::Float4::broadcast(kInf), hi = sse::Float4::broadcast(-kInf);
  uint32_t count = 0;
  void grow(const Bins& bins, int axis, int k) {
    const float* b = bins.box[axis][k];
    lo = sse::vmin(sse::Float4::load(b), lo);
    hi = sse::vmax(sse::Float4::load(b + 4), hi);
    count += bins.count[axis][k];
  }
  float half_area() const { return sse::half_area(lo, hi); }
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = kInf;
  BBox left, right;
};

// Bin of a centroid coordinate; NaN and out-of-range values are clamped to the end bins. Written as
// the x86 max and min (NaN gives the second operand) so that Builder::bin_range's 4-lane form gives
// the same bin.
inline int bin_of(float c, float lo, float scale, int bins) {
  float f = (c - lo) * scale;
  f = f > 0.0f ? f : 0.0f;
  const float last = float(bins - 1);
  return int(f < last ? f : last);
}

// The floats in increasing order as unsigned integers: −NaN < −inf < … < −0 < +0 < … < +inf < +NaN.
inline uint32_t float_rank(float f) {
  const uint32_t b = std::bit_cast<uint32_t>(f);
  return (b & 0x80000000u) != 0 ? ~b : b | 0x80000000u;
}
inline float float_of_rank(uint32_t r) {
  return std::bit_cast<float>((r & 0x80000000u) != 0 ? r & 0x7fffffffu : ~r);
}

// The least centroid coordinate whose bin_of is past `last_left`, so that for every c
//   bin_of(c, lo, scale, bins) <= last_left  ⇔  !(c >= right_threshold(lo, scale, bins, last_left))
// (NaN included: bin 0, and no comparison with NaN holds); NaN when no bin is past it. bin_of is
// non-decreasing in c (a subtraction, a multiplication by scale >= 0, a clamp and a truncation all
// are), so a search over the floats in order finds it; the partition then tests one comparison a
// primitive instead of the bin arithmetic.
inline float right_threshold(float lo, float scale, int bins, int last_left) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  if (bin_of(inf, lo, scale, bins) <= last_left) return std::numeric_limits<float>::quiet_NaN();
  if (bin_of(-inf, lo, scale, bins) > last_left) return -inf;
  uint32_t left = float_rank(-inf), right = float_rank(inf);  // bins: <= last_left, > last_left
  while (right - left > 1) {
    const uint32_t mid = left + (right - left) / 2;
    (bin_of(float_of_rank(mid), lo, scale, bins) <= last_left ? left : right) = mid;
  }
  return float_of_rank(right);
}

// The cheapest split of binned primitives over `nbins` bins a side, along the axes whose centroid
// extent `ext` is positive: cost left.half_area · leaf_cost(left count) + right's, both sides
// non-empty; the first cheapest bin on ties (axes in order). The sweeps visit only the occupied bins:
// an empty bin changes neither side, so a split after it costs the same as the one before it and is
// never strictly cheaper — skipping it keeps the choice, and a small range's sweep no longer walks
// (and branches on) the many empty bins.
template <class LeafCost>
Split cheapest_split(const Bins& bins, int nbins, Vec3f ext, const LeafCost& leaf_cost) {
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(ext[axis] > 0.0f)) continue;
    // used[0, m): the occupied bins in increasing order, gathered without branches
    const uint32_t* count = bins.count[axis];
    int used[kMaxBins];
    int m = 0;
    for (int k = 0; k < nbins; ++k) {
      used[m] = k;
      m += count[k] != 0 ? 1 : 0;
    }
    // right_*[j]: bins used[j, m)
    float right_area[kMaxBins];
    uint32_t right_count[kMaxBins];
    SweepBox acc;
    for (int j = m - 1; j > 0; --j) {
      acc.grow(bins, axis, used[j]);
      right_area[j] = acc.half_area();
      right_count[j] = acc.count;
    }
    SweepBox left;
    int best_j = -1;
    for (int j = 0; j + 1 < m; ++j) {  // both sides non-empty
      left.grow(bins, axis, used[j]);
      const float cost =
          left.half_area() * leaf_cost(left.count) + right_area[j + 1] * leaf_cost(right_count[j + 1]);
      if (cost < best.cost) {
        best.cost = cost;
        best.axis = axis;
        best.bin = used[j];
        best_j = j;
      }
    }
    if (best_j >= 0) {  // boxes of the chosen split
      BinBox l, r;
      for (int j = 0; j < m; ++j) (j <= best_j ? l : r).grow(bins.at(axis, used[j]));
      best.left = l.box();
      best.right = r.box();
    }
  }
  return best;
}

}  // namespace rayvec::sah_bins
