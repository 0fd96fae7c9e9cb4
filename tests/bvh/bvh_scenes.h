// Scenes and rays shared by the BVH tests: random soups, a closed sphere, flat and tiny meshes.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "rays/ray.h"
#include "geometry/triangle_mesh.h"

namespace rayvec::test {

// n random triangles in [-1, 1]^3 of edge length up to `size`, with a few exact duplicates (ties at
// equal t must go to the lower id).
inline TriangleMesh random_soup(int n, float size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-1.0f, 1.0f), off(-size, size);
  TriangleMesh m;
  for (int i = 0; i < n; ++i) {
    if (i % 17 == 16) {  // duplicate an earlier triangle
      const auto& t = m.triangles[rng() % m.triangles.size()];
      m.add_triangle(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
      continue;
    }
    const Vec3f c{pos(rng), pos(rng), pos(rng)};
    m.add_triangle(c + Vec3f{off(rng), off(rng), off(rng)}, c + Vec3f{off(rng), off(rng), off(rng)},
                   c + Vec3f{off(rng), off(rng), off(rng)});
  }
  return m;
}

// A closed UV sphere of radius r (shared vertices), `rings` × `segments` quads as triangle pairs.
inline TriangleMesh sphere(float r, int rings, int segments) {
  TriangleMesh m;
  const float pi = 3.14159265358979f;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const float th = pi * float(i) / float(rings), ph = 2 * pi * float(j) / float(segments);
      m.positions.push_back(
          {r * std::sin(th) * std::cos(ph), r * std::cos(th), r * std::sin(th) * std::sin(ph)});
    }
  auto at = [&](int i, int j) { return uint32_t(i * segments + (j % segments)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      if (i > 0) m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i < rings - 1) m.triangles.push_back({at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
    }
  return m;
}

// A flat grid of 2·n² triangles in the plane z = 0 covering [0, n]^2 (every triangle coplanar).
inline TriangleMesh flat_grid(int n) {
  TriangleMesh m;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec3f a{float(x), float(y), 0}, b{float(x + 1), float(y), 0};
      const Vec3f c{float(x), float(y + 1), 0}, d{float(x + 1), float(y + 1), 0};
      m.add_triangle(a, b, c);
      m.add_triangle(b, d, c);
    }
  return m;
}

// Adds `count` long thin triangles in random directions through [-1, 1]^3 (sticks about 2 long,
// 0.02 wide), drawn from `rng`.
inline void add_sticks(TriangleMesh& m, int count, std::mt19937& rng) {
  std::uniform_real_distribution<float> pos(-1.0f, 1.0f);
  for (int i = 0; i < count; ++i) {
    const Vec3f c{pos(rng), pos(rng), pos(rng)};
    Vec3f u{pos(rng), pos(rng), pos(rng)};
    u = u * (1.0f / std::max(length(u), 0.1f));
    const Vec3f w{0.01f * pos(rng), 0.01f * pos(rng), 0.01f * pos(rng)};
    m.add_triangle(c - u, c + u, c + w);
  }
}

// n sticks alone: like architectural models' long faces, whose leaf boxes shrink most when a leaf
// holds fewer of them.
inline TriangleMesh sticks(int n, unsigned seed) {
  std::mt19937 rng(seed);
  TriangleMesh m;
  add_sticks(m, n, rng);
  return m;
}

// n small random triangles (edges up to 0.05) in [-1, 1]^3, crossed by n / 50 sticks and two large
// floor triangles: the long ones make the boxes of object splits overlap, so the builder's spatial
// splits reference them in several leaves.
inline TriangleMesh long_slivers(int n, unsigned seed) {
  std::mt19937 rng(seed);
  TriangleMesh m = random_soup(n, 0.05f, seed + 1);
  m.add_triangle({-1.5f, -1.0f, -1.5f}, {1.5f, -1.0f, -1.5f}, {-1.5f, -1.0f, 1.5f});
  m.add_triangle({1.5f, -1.0f, -1.5f}, {1.5f, -1.0f, 1.5f}, {-1.5f, -1.0f, 1.5f});
  add_sticks(m, n / 50, rng);
  return m;
}

// Random rays: origins in [-s, s]^3, directions uniform plus axis-parallel ones (some with −0
// components), some with finite tmax.
inline std::vector<Ray> random_rays(int n, float s, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-s, s), dir(-1.0f, 1.0f), len(0.1f, 3.0f);
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    Ray r;
    r.org = {pos(rng), pos(rng), pos(rng)};
    switch (i % 8) {
      case 0: r.dir = {0.0f, 0.0f, dir(rng) < 0 ? -1.0f : 1.0f}; break;
      case 1: r.dir = {-0.0f, dir(rng) < 0 ? -2.0f : 2.0f, 0.0f}; break;
      case 2: r.dir = {dir(rng) < 0 ? -1.0f : 1.0f, -0.0f, -0.0f}; break;
      default: r.dir = {dir(rng), dir(rng), dir(rng)}; break;
    }
    if (i % 5 == 0) r.tmax = len(rng);
    if (i % 7 == 0) r.tmin = len(rng) * 0.1f;
    rays.push_back(r);
  }
  return rays;
}

// Packets of P lanes holding P/4 consecutive rays four times each (lane k: ray P/4·p + k mod P/4).
// Copies follow each other through the tree, so at least four lanes reach every leaf a ray visits
// and no packet diverges into single rays (kSingleRayLanes): every leaf runs the packet kernel.
inline std::vector<Ray> four_copies(const std::vector<Ray>& rays, int P) {
  const std::size_t distinct = std::size_t(P / 4);
  std::vector<Ray> out;
  for (std::size_t i = 0; i < rays.size(); i += distinct)
    for (int k = 0; k < P; ++k) out.push_back(rays[std::min(i + std::size_t(k) % distinct, rays.size() - 1)]);
  return out;
}

}  // namespace rayvec::test
