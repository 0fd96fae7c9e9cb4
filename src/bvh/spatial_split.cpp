#include "bvh/spatial_split.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/triangle_mesh.h"
#include "simd/float4_sse.h"

namespace rayvec {
namespace {

constexpr int kMaxSpatialBins = 32;
constexpr float kInf = std::numeric_limits<float>::infinity();
// Relative widening of a computed crossing point: its coordinates are within a few ulps of the
// exact ones (one division, one multiply-add over the edge), 2^-20 is 16 ulps of the larger end.
constexpr float kCrossingSlack = 1.0f / 1048576.0f;

struct Bounds {
  float lo[3] = {kInf, kInf, kInf};
  float hi[3] = {-kInf, -kInf, -kInf};
  void grow(const float* l, const float* h) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], l[a]);
      hi[a] = std::max(hi[a], h[a]);
    }
  }
  bool empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]); }
  float half_area() const {
    if (empty()) return 0.0f;
    const float x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return x * y + y * z + z * x;
  }
};

bool finite_box(const BuildPrim& r) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(r.lo[a]) || !std::isfinite(r.hi[a])) return false;
  return true;
}

}  // namespace

SpatialSplitter::SpatialSplitter(const TriangleMesh& mesh, int bins, uint32_t leaf_block)
    : mesh_(mesh), bins_(std::clamp(bins, 2, kMaxSpatialBins)), leaf_block_(std::max(leaf_block, 1u)) {}

float SpatialSplitter::plane_at(const BBox& box, int axis, int k) const {
  return box.lo[axis] + (box.hi[axis] - box.lo[axis]) * (float(k) / float(bins_));
}

// Bins of r's low and high ends along `axis`: bin k spans [plane_at(k), plane_at(k + 1)), the
// last bin up to the box's end. One bin (first == last) for a reference that is not to be clipped:
// a non-finite box (an infinite vertex, or no finite one); such a triangle is never hit.
void SpatialSplitter::bin_span(const BuildPrim& r, const BBox& box, int axis, bool splittable, int& first,
                               int& last) const {
  const float scale = float(bins_) / (box.hi[axis] - box.lo[axis]);
  const float last_bin = float(bins_ - 1);
  auto bin = [&](float x) {  // clamped before the conversion: NaN → 0, ±inf → the end bins
    float f = (x - box.lo[axis]) * scale;
    f = f > 0.0f ? f : 0.0f;
    return int(f < last_bin ? f : last_bin);
  };
  first = bin(r.lo[axis]);
  last = splittable ? std::max(first, bin(r.hi[axis])) : first;
}

void SpatialSplitter::clip(const BuildPrim& r, int axis, float at, BuildPrim& left, BuildPrim& right,
                           bool& has_left, bool& has_right) const {
  Vec3f v[3];
  for (int c = 0; c < 3; ++c) v[c] = mesh_.vertex(r.id, c);
  Bounds side[2];
  for (int i = 0; i < 3; ++i) {
    const Vec3f a = v[i], b = v[(i + 1) % 3];
    const float p[3] = {a.x, a.y, a.z};
    if (a[axis] <= at) side[0].grow(p, p);
    if (a[axis] >= at) side[1].grow(p, p);
    if ((a[axis] < at && at < b[axis]) || (b[axis] < at && at < a[axis])) {
      const float t = (at - a[axis]) / (b[axis] - a[axis]);
      float lo[3], hi[3];
      for (int c = 0; c < 3; ++c) {
        const float q = a[c] + t * (b[c] - a[c]);
        const float slack = (std::fabs(a[c]) + std::fabs(b[c])) * kCrossingSlack;
        lo[c] = c == axis ? at : q - slack;
        hi[c] = c == axis ? at : q + slack;
      }
      side[0].grow(lo, hi);
      side[1].grow(lo, hi);
    }
  }
  // within r's box (the reference may already be a clipped part) and on its side of the plane
  for (int a = 0; a < 3; ++a)
    for (Bounds& s : side) {
      s.lo[a] = std::max(s.lo[a], r.lo[a]);
      s.hi[a] = std::min(s.hi[a], r.hi[a]);
    }
  side[0].hi[axis] = std::min(side[0].hi[axis], at);
  side[1].lo[axis] = std::max(side[1].lo[axis], at);
  BuildPrim* out[2] = {&left, &right};
  for (int s = 0; s < 2; ++s)
    *out[s] = BuildPrim{{side[s].lo[0], side[s].lo[1], side[s].lo[2]},
                        r.id,
                        {side[s].hi[0], side[s].hi[1], side[s].hi[2]},
                        0.0f};
  has_left = !side[0].empty();
  has_right = !side[1].empty();
}

SpatialSplit SpatialSplitter::find(const BuildPrim* refs, uint32_t n, const BBox& box, uint32_t room) const {
  using sse::Float4;
  SpatialSplit best;
  best.cost = kInf;
  // one pass over the references bins all three axes (4-lane boxes, lane 3 unused)
  struct alignas(16) Bin {
    float lo[4], hi[4];
  };
  Bin bin[3][kMaxSpatialBins];
  uint32_t entry[3][kMaxSpatialBins] = {}, exit[3][kMaxSpatialBins] = {};
  float plane[3][kMaxSpatialBins + 1];
  bool usable[3];
  for (int a = 0; a < 3; ++a) {
    const float extent = box.hi[a] - box.lo[a];
    usable[a] = extent > 0.0f && std::isfinite(extent);
    for (int k = 0; k < bins_; ++k) {
      Float4::broadcast(kInf).store(bin[a][k].lo);
      Float4::broadcast(-kInf).store(bin[a][k].hi);
    }
    for (int k = 0; k <= bins_; ++k) plane[a][k] = plane_at(box, a, k);
  }
  for (uint32_t i = 0; i < n; ++i) {
    const BuildPrim& r = refs[i];
    const Float4 lo = Float4::load(r.lo).xyz(), hi = Float4::load(r.hi);
    const bool splittable = finite_box(r);
    for (int a = 0; a < 3; ++a) {
      if (!usable[a]) continue;
      int first, last;
      bin_span(r, box, a, splittable, first, last);
      ++entry[a][first];
      ++exit[a][last];
      if (first == last) {
        Bin& b = bin[a][first];
        vmin(lo, Float4::load(b.lo)).store(b.lo);
        vmax(hi, Float4::load(b.hi)).store(b.hi);
        continue;
      }
      // the reference's box cut at the bin planes (the triangle itself is clipped only by
      // partition(): clipping at every plane here made the search most of the build's time)
      for (int k = first; k <= last; ++k) {
        const Float4 l = k > first ? lo.with_lane(a, plane[a][k]) : lo;
        const Float4 h = k < last ? hi.with_lane(a, plane[a][k + 1]) : hi;
        Bin& b = bin[a][k];
        vmin(l, Float4::load(b.lo)).store(b.lo);
        vmax(h, Float4::load(b.hi)).store(b.hi);
      }
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!usable[axis]) continue;
    // right sides: bins [j, bins)
    float right_area[kMaxSpatialBins];
    uint32_t right_count[kMaxSpatialBins];
    Bounds acc;
    uint32_t count = 0;
    for (int j = bins_ - 1; j > 0; --j) {
      acc.grow(bin[axis][j].lo, bin[axis][j].hi);
      count += exit[axis][j];
      right_area[j] = acc.half_area();
      right_count[j] = count;
    }
    Bounds left;
    uint32_t left_count = 0;
    for (int j = 1; j < bins_; ++j) {
      left.grow(bin[axis][j - 1].lo, bin[axis][j - 1].hi);
      left_count += entry[axis][j - 1];
      const uint32_t rc = right_count[j];
      if (left_count == 0 || rc == 0 || left_count >= n || rc >= n || left_count + rc - n > room) continue;
      const float cost = left.half_area() * leaf_cost(left_count) + right_area[j] * leaf_cost(rc);
      if (cost < best.cost) best = SpatialSplit{axis, j, cost, left_count, rc};
    }
  }
  return best;
}

uint32_t SpatialSplitter::partition(BuildPrim* refs, uint32_t n, const BBox& box, const SpatialSplit& split,
                                    std::vector<BuildPrim>& right) const {
  const float at = plane_at(box, split.axis, split.plane);
  uint32_t w = 0;  // each reference yields at most one left one, so w never passes the read index
  for (uint32_t i = 0; i < n; ++i) {
    const BuildPrim r = refs[i];
    int first, last;
    bin_span(r, box, split.axis, finite_box(r), first, last);
    if (last < split.plane) {
      refs[w++] = r;
    } else if (first >= split.plane) {
      right.push_back(r);
    } else {
      BuildPrim a, b;
      bool has_a, has_b;
      clip(r, split.axis, at, a, b, has_a, has_b);
      if (has_a) refs[w++] = a;
      if (has_b) right.push_back(b);
      if (!has_a && !has_b) refs[w++] = r;  // not expected (r's box holds part of it); keep it whole
    }
  }
  return w;
}

}  // namespace rayvec
