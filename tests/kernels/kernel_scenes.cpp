#include "kernels/kernel_scenes.h"

#include <array>
#include <cmath>

namespace rayvec::test {

Vec3f random_point(SplitMix64& rng, float lo, float hi) {
  return {lo + (hi - lo) * rng.unit_float(), lo + (hi - lo) * rng.unit_float(),
          lo + (hi - lo) * rng.unit_float()};
}

Vec3f random_direction(SplitMix64& rng) {
  for (;;) {
    const Vec3f d = random_point(rng, -1.0f, 1.0f);
    const float l2 = dot(d, d);
    if (l2 > 0.01f && l2 <= 1.0f) return d;
  }
}

KernelScene random_scene() {
  KernelScene s{"random", paper_triangles(400, 7), {}};
  s.mesh.add_triangle({0.3f, 0.3f, 0.3f}, {0.3001f, 0.3f, 0.3f}, {0.3f, 0.3001f, 0.3f});
  s.mesh.add_triangle({0.1f, 0.1f, 0.1f}, {0.2f, 0.2f, 0.2f}, {0.3f, 0.3f, 0.3f});
  SplitMix64 rng(11);
  for (int i = 0; i < 3000; ++i) {
    Ray r{random_point(rng, -0.5f, 1.5f), random_direction(rng)};
    if (i % 3 == 1) r.tmin = 0.2f * rng.unit_float();
    if (i % 3 == 2) r.tmax = 0.3f + rng.unit_float();
    s.rays.push_back(r);
  }
  const RayBatch camera = paper_camera_rays(30);
  for (std::size_t i = 0; i < camera.size(); ++i) s.rays.push_back(camera[i]);
  return s;
}

KernelScene sphere_scene() {
  KernelScene s{"sphere", {}, {}};
  const int rings = 24, segments = 48;
  const float pi = 3.14159265358979f;
  s.mesh.positions.push_back({0, 0, 1});
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const float th = pi * r / rings, ph = 2 * pi * k / segments;
      s.mesh.positions.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  s.mesh.positions.push_back({0, 0, -1});
  const uint32_t south = uint32_t(s.mesh.positions.size() - 1);
  auto at = [&](int r, int k) { return uint32_t(1 + (r - 1) * segments + (k % segments)); };
  for (int k = 0; k < segments; ++k) s.mesh.triangles.push_back({0, at(1, k), at(1, k + 1)});
  for (int r = 1; r + 1 < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      s.mesh.triangles.push_back({at(r, k), at(r + 1, k), at(r + 1, k + 1)});
      s.mesh.triangles.push_back({at(r, k), at(r + 1, k + 1), at(r, k + 1)});
    }
  for (int k = 0; k < segments; ++k)
    s.mesh.triangles.push_back({at(rings - 1, k), south, at(rings - 1, k + 1)});
  SplitMix64 rng(23);
  for (int i = 0; i < 3000; ++i) {
    const Vec3f inside = random_point(rng, -0.5f, 0.5f);
    if (i % 2 == 0) {
      s.rays.push_back(Ray{inside, random_direction(rng)});
    } else {
      const Vec3f d = random_direction(rng);
      const Vec3f o = inside - d * (3.0f / length(d));
      s.rays.push_back(Ray{o, inside - o});
    }
  }
  return s;
}

KernelScene grid_scene() {
  KernelScene s{"grid", {}, {}, true};
  const int n = 16;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.mesh.positions.push_back({float(i) / n, float(j) / n, 0.5f});
  auto at = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  SplitMix64 rng(5);
  for (int k = 0; k < 2000; ++k) {
    const float a = float(1 + k % (n - 1)) / n, b = 0.05f + 0.9f * rng.unit_float();
    const Vec3f target =
        k % 3 == 0 ? Vec3f{a, b, 0.5f} : (k % 3 == 1 ? Vec3f{b, a, 0.5f} : Vec3f{b, b, 0.5f});
    const Vec3f o = random_point(rng, 0.0f, 1.0f) + Vec3f{0, 0, 1.0f};
    s.rays.push_back(Ray{o, target - o});
  }
  return s;
}

KernelScene hard_scene() {
  KernelScene s{"hard", paper_triangles(60, 9), {}, true};
  const Vec3f a{0.2f, 0.2f, 2.0f}, b{0.8f, 0.2f, 2.0f}, c{0.2f, 0.8f, 2.0f};
  for (uint32_t at : {5u, 17u, 40u}) {
    const auto n = uint32_t(s.mesh.positions.size());
    s.mesh.triangles.insert(s.mesh.triangles.begin() + at, std::array<uint32_t, 3>{n, n + 1, n + 2});
    for (const Vec3f& p : {a, b, c}) s.mesh.positions.push_back(p);
  }
  s.mesh.add_triangle({0.4f, 0.4f, 1.0f}, {0.5f, 0.5f, 1.0f}, {0.6f, 0.6f, 1.0f});  // collinear
  s.mesh.add_triangle({0.3f, 0.3f, 1.5f}, {0.3f, 0.3f, 1.5f}, {0.3f, 0.3f, 1.5f});  // a point
  const float nan = std::nanf("");
  const Vec3f down{0, 0, 1};
  for (const Vec3f& target : {a, b, c, (a + b) * 0.5f, (b + c) * 0.5f, Vec3f{0.4f, 0.4f, 2.0f}}) {
    const Vec3f o = target - Vec3f{0.01f, 0.02f, 3.0f};
    s.rays.push_back(Ray{o, target - o});
    s.rays.push_back(Ray{o, target - o, 1.0f});        // tmin exactly at the hit
    s.rays.push_back(Ray{o, target - o, 0.0f, 1.0f});  // tmax exactly at the hit
    s.rays.push_back(Ray{o, target - o, 1.0f, 1.0f});  // both
  }
  s.rays.push_back(Ray{{0.0f, 0.5f, 2.0f}, {1, 0, 0}});  // in the duplicates' plane
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, down});       // through the collinear one and the point
  s.rays.push_back(Ray{{nan, 0.4f, 0.0f}, down});
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, {0, nan, 1}});
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, {0, 0, 0}});
  s.rays.push_back(Ray{{0.4f, 0.4f, 0.0f}, down, nan});
  SplitMix64 rng(31);
  for (int i = 0; i < 500; ++i) s.rays.push_back(Ray{random_point(rng, -0.5f, 1.5f), random_direction(rng)});
  return s;
}

std::vector<Hit> closest_one_by_one(const TriangleKernels& k, const TriangleSoA& soa,
                                    const std::vector<Ray>& rays) {
  std::vector<Hit> hits(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) k.closest(soa.arrays(), 0, soa.size(), rays[i], hits[i]);
  return hits;
}

}  // namespace rayvec::test
