#include "scene/smooth_normals.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace rayvec {
namespace {

// The normals being summed: one slot per (vertex, group) that a wanted triangle uses. Most vertices
// lie in one group, so a vertex's first slot sits in an array over the vertices the triangles use
// (one object's, in a scene of many); the rare slots of a vertex on a crease between groups go to a
// map.
class Slots {
 public:
  Slots(uint32_t lowest, uint32_t highest)
      : lowest_(lowest), first_(highest >= lowest ? highest - lowest + 1 : 0, kNoSmoothNormal) {}

  uint32_t find_or_add(uint32_t vertex, uint32_t group) {
    uint32_t& first = first_[vertex - lowest_];
    if (first == kNoSmoothNormal) return first = add(group);
    if (group_[first] == group) return first;
    const auto [it, fresh] = more_.try_emplace(key(vertex, group), 0);
    if (fresh) it->second = add(group);
    return it->second;
  }

  uint32_t find(uint32_t vertex, uint32_t group) const {
    const uint32_t first = first_[vertex - lowest_];
    if (first == kNoSmoothNormal || group_[first] == group) return first;
    const auto it = more_.find(key(vertex, group));
    return it == more_.end() ? kNoSmoothNormal : it->second;
  }

  std::size_t size() const { return group_.size(); }

 private:
  static uint64_t key(uint32_t vertex, uint32_t group) { return uint64_t(vertex) << 32 | group; }
  uint32_t add(uint32_t group) {
    group_.push_back(group);
    return static_cast<uint32_t>(group_.size() - 1);
  }

  uint32_t lowest_;
  std::vector<uint32_t> first_;  // per vertex from lowest_: its first slot
  std::vector<uint32_t> group_;  // per slot
  std::unordered_map<uint64_t, uint32_t> more_;
};

}  // namespace

SmoothedNormals smooth_normals(std::span<const Vec3f> positions,
                               std::span<const std::array<uint32_t, 3>> triangles,
                               std::span<const uint32_t> group, std::span<const uint32_t> wanted) {
  SmoothedNormals out;
  out.corners.reserve(wanted.size());
  uint32_t lowest = UINT32_MAX, highest = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (group[t] != 0)
      for (const uint32_t v : triangles[t]) {
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
      }
  Slots slots(lowest, highest);
  for (const uint32_t t : wanted) {
    std::array<uint32_t, 3> c{kNoSmoothNormal, kNoSmoothNormal, kNoSmoothNormal};
    if (group[t] != 0)
      for (int k = 0; k < 3; ++k) c[k] = slots.find_or_add(triangles[t][k], group[t]);
    out.corners.push_back(c);
  }

  // each triangle of a group adds its unit normal, weighted by its angle, at the slots of its corners
  std::vector<Vec3d> sum(slots.size(), Vec3d{0, 0, 0});
  std::vector<double> weight(slots.size(), 0.0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (group[t] == 0) continue;
    const auto& v = triangles[t];
    const std::array<uint32_t, 3> s{slots.find(v[0], group[t]), slots.find(v[1], group[t]),
                                    slots.find(v[2], group[t])};
    if (s[0] == kNoSmoothNormal && s[1] == kNoSmoothNormal && s[2] == kNoSmoothNormal) continue;
    const auto p0 = Vec3d(positions[v[0]]), p1 = Vec3d(positions[v[1]]), p2 = Vec3d(positions[v[2]]);
    const Vec3d e01 = p1 - p0, e02 = p2 - p0, e12 = p2 - p1;
    const Vec3d n = cross(e01, e02);
    const double twice_area = length(n);
    if (!(twice_area > 0) || !std::isfinite(twice_area)) continue;
    const Vec3d unit = n * (1 / twice_area);
    // The angle between two edges is atan2(|a × b|, a · b), and |a × b| is twice the area for each
    // pair; the third angle is what the other two leave of π (its error is absolute, ~1e-16, as
    // atan2's is).
    const double a0 = std::atan2(twice_area, dot(e01, e02)), a1 = std::atan2(twice_area, -dot(e01, e12));
    const std::array<double, 3> angle{a0, a1, std::max(0.0, std::numbers::pi - a0 - a1)};
    for (int k = 0; k < 3; ++k) {
      if (s[k] == kNoSmoothNormal) continue;
      sum[s[k]] += unit * angle[k];
      weight[s[k]] += angle[k];
    }
  }

  // A sum much shorter than its weight is a fold (normals that cancel): no direction to trust.
  out.normals.resize(slots.size(), Vec3f{0, 0, 0});
  std::vector<bool> usable(slots.size(), false);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const double len = length(sum[i]);
    if (!(len > 1e-6 * weight[i])) continue;
    out.normals[i] = Vec3f(sum[i] / len);
    usable[i] = true;
  }
  for (auto& c : out.corners)
    if (c[0] == kNoSmoothNormal || !usable[c[0]] || !usable[c[1]] || !usable[c[2]])
      c = {kNoSmoothNormal, kNoSmoothNormal, kNoSmoothNormal};
  return out;
}

}  // namespace rayvec
