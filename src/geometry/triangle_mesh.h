// TriangleMesh: indexed triangles, the form every loader produces and every accelerator consumes.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace rayvec {

struct TriangleMesh {
  std::vector<Vec3f> positions;
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into positions; triangle id = index here

  std::size_t size() const { return triangles.size(); }
  Vec3f vertex(std::size_t tri, int corner) const { return positions[triangles[tri][corner]]; }
  void add_triangle(Vec3f a, Vec3f b, Vec3f c) {
    const auto base = static_cast<uint32_t>(positions.size());
    positions.insert(positions.end(), {a, b, c});
    triangles.push_back({base, base + 1, base + 2});
  }
};

}  // namespace rayvec
