#include "bench/paper_scene.h"

#include <cmath>

namespace rayvec {

uint64_t SplitMix64::next() {
  uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

float SplitMix64::unit_float() { return float(next() >> 40) * 0x1p-24f; }

TriangleMesh paper_triangles(uint32_t count, uint64_t seed) {
  SplitMix64 rng(seed);
  TriangleMesh mesh;
  mesh.positions.reserve(std::size_t(count) * 3);
  mesh.triangles.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    Vec3f v[3];
    for (auto& p : v) {
      p.x = rng.unit_float();
      p.y = rng.unit_float();
      p.z = rng.unit_float();
    }
    mesh.add_triangle(v[0], v[1], v[2]);
  }
  return mesh;
}

RayBatch paper_camera_rays(uint32_t side) {
  RayBatch rays;
  rays.reserve(std::size_t(side) * side);
  const Vec3d eye{0.5, 0.5, -1.5};
  for (uint32_t j = 0; j < side; ++j)
    for (uint32_t i = 0; i < side; ++i) {
      const Vec3d target{(i + 0.5) / side, (j + 0.5) / side, 0.0};
      const Vec3d d = target - eye;
      const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      rays.push_back(
          Ray{Vec3f(eye), Vec3f{float(d.x / len), float(d.y / len), float(d.z / len)}, 0.0f, kInf});
    }
  return rays;
}

}  // namespace rayvec
