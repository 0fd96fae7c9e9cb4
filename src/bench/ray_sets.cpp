#include "bench/ray_sets.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

Vec3f to_float(Vec3d v) { return {float(v.x), float(v.y), float(v.z)}; }

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double uniform01(uint64_t& state) { return double(splitmix64(state) >> 40) / double(1u << 24); }

Vec3d hit_point(const Ray& r, const Hit& h) { return Vec3d(r.org) + Vec3d(r.dir) * double(h.t); }

}  // namespace

BenchCamera frame_mesh(const TriangleMesh& mesh, int width, int height) {
  BBox box;
  for (const Vec3f& p : mesh.positions) box.grow(p);
  const double half_fov = 22.5 * std::numbers::pi / 180.0;
  const BoxFraming<double> framing = frame_box(box, Vec3d{0.5, 0.5, 1.0}, half_fov, 1.05);
  BenchCamera c;
  c.center = framing.center;
  c.eye = framing.eye;
  c.radius = framing.radius;
  c.frame = look_at_frame(c.eye, c.center, Vec3d{0, 1, 0});
  c.th = std::tan(half_fov);
  c.width = width;
  c.height = height;
  return c;
}

Ray primary_ray(const BenchCamera& c, int x, int y) {
  const double u = (2.0 * (x + 0.5) / c.width - 1.0) * c.th * c.width / c.height;
  const double v = (1.0 - 2.0 * (y + 0.5) / c.height) * c.th;
  return Ray{to_float(c.eye), to_float(c.frame.direction(u, v)), 0.0f, kInf};
}

RaySet primary_rays(const BenchCamera& c) {
  RaySet s;
  s.rays.reserve(std::size_t(c.width) * c.height);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      s.rays.push_back(primary_ray(c, x, y));
      s.pixel.push_back(uint32_t(y * c.width + x));
    }
  return s;
}

RaySet primary_tiles(const BenchCamera& c, std::vector<uint32_t>& tile_start) {
  RaySet s;
  tile_start.clear();
  for (int ty = 0; ty < c.height; ty += 4)
    for (int tx = 0; tx < c.width; tx += 4) {
      tile_start.push_back(uint32_t(s.rays.size()));
      for (int y = ty; y < ty + 4 && y < c.height; ++y)
        for (int x = tx; x < tx + 4 && x < c.width; ++x) {
          s.rays.push_back(primary_ray(c, x, y));
          s.pixel.push_back(uint32_t(y * c.width + x));
        }
    }
  tile_start.push_back(uint32_t(s.rays.size()));
  return s;
}

RaySet shadow_rays(const BenchCamera& c, const RaySet& primary, std::span<const Hit> hits) {
  RaySet s;
  const Vec3d light = c.eye + Vec3d{0, 2 * c.radius, 0};
  const double eps = 1e-4 * c.radius;
  for (std::size_t i = 0; i < primary.rays.size(); ++i) {
    if (!hits[i].hit()) continue;
    const Vec3d p = hit_point(primary.rays[i], hits[i]);
    const Vec3d to_light = light - p;
    const double dist = length(to_light);
    s.rays.push_back(Ray{to_float(p), to_float(to_light * (1.0 / dist)), float(eps), float(dist - eps)});
    s.pixel.push_back(primary.pixel[i]);
  }
  return s;
}

RaySet incoherent_rays(const BenchCamera& c, const TriangleMesh& mesh, const RaySet& primary,
                       std::span<const Hit> hits) {
  RaySet s;
  const double eps = 1e-4 * c.radius;
  for (std::size_t i = 0; i < primary.rays.size(); ++i) {
    if (!hits[i].hit()) continue;
    const Ray& r = primary.rays[i];
    const auto tri = std::size_t(hits[i].tri);
    const Vec3d v0(mesh.vertex(tri, 0)), v1(mesh.vertex(tri, 1)), v2(mesh.vertex(tri, 2));
    Vec3d n = normalize(cross(v1 - v0, v2 - v0));
    if (dot(n, Vec3d(r.dir)) > 0) n = -n;
    const Vec3d t = normalize(cross(n, std::abs(n.x) > 0.5 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0}));
    const Vec3d b = cross(n, t);
    uint64_t state = primary.pixel[i];
    const double z = uniform01(state), phi = 2 * std::numbers::pi * uniform01(state);
    const double sr = std::sqrt(std::max(0.0, 1 - z * z));
    const Vec3d dir = t * (sr * std::cos(phi)) + b * (sr * std::sin(phi)) + n * z;
    s.rays.push_back(Ray{to_float(hit_point(r, hits[i])), to_float(dir), float(eps), kInf});
    s.pixel.push_back(primary.pixel[i]);
  }
  return s;
}

uint64_t hit_checksum(const RaySet& set, std::span<const Hit> hits) {
  uint64_t sum = 0;
  for (std::size_t i = 0; i < set.rays.size(); ++i)
    if (hits[i].hit()) sum += (uint64_t(set.pixel[i]) + 1) * (uint64_t(hits[i].tri) + 1);
  return sum;
}

uint64_t occluded_checksum(const RaySet& set, std::span<const uint8_t> occluded) {
  uint64_t sum = 0;
  for (std::size_t i = 0; i < set.rays.size(); ++i)
    if (occluded[i]) sum += uint64_t(set.pixel[i]) + 1;
  return sum;
}

}  // namespace rayvec
