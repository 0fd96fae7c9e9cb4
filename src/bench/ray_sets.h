// The ray sets of `rayvec bench rays`, defined exactly so another tracer can reproduce them:
// primary rays of a pinhole camera that frames the mesh, shadow rays toward a light above the eye,
// and incoherent rays on the hemisphere of each primary hit's geometric normal.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "rays/pinhole_camera.h"
#include "rays/ray.h"

namespace rayvec {

struct TriangleMesh;

// The framing camera, in double (rays are rounded to float at the end), i.e. frame_box and
// look_at_frame of rays/pinhole_camera.h with these arguments:
// lo, hi = bounding box of all vertices; C = (lo + hi)/2; R = max(|hi − lo|/2, 1e-30);
// D = normalize(0.5, 0.5, 1); eye = C + D · 1.05 · R / sin(22.5°); fwd = normalize(C − eye);
// right = normalize(cross(fwd, (0,1,0))); up = cross(right, fwd); th = tan(22.5°). The 45° field is
// vertical whatever the aspect: a portrait W < H image may crop the mesh at its sides.
struct BenchCamera {
  Vec3d center, eye;
  PinholeFrame<double> frame;  // fwd, right, up
  double radius = 0, th = 0;
  int width = 0, height = 0;
};
BenchCamera frame_mesh(const TriangleMesh& mesh, int width, int height);

// Pixel (x, y), y = 0 at the top: u = (2(x+0.5)/W − 1)·th·W/H, v = (1 − 2(y+0.5)/H)·th,
// dir = normalize(fwd + u·right + v·up), origin eye, tmin = 0, tmax = +inf.
Ray primary_ray(const BenchCamera& cam, int x, int y);

// Rays plus the pixel each belongs to (for checksums).
struct RaySet {
  std::vector<Ray> rays;
  std::vector<uint32_t> pixel;
};

// All pixels in row-major order (pixel index = y·W + x).
RaySet primary_rays(const BenchCamera& cam);
// The same rays ordered by 4×4 tiles (row-major tiles, row-major inside; edge tiles are smaller),
// with tile_start[k] the first ray of tile k (and a final entry = rays.size()).
RaySet primary_tiles(const BenchCamera& cam, std::vector<uint32_t>& tile_start);

// For each primary hit p = eye + t·dir: a ray from p toward L = eye + (0, 2R, 0), direction
// normalized, tmin = 1e−4·R, tmax = |L − p| − 1e−4·R (any-hit).
RaySet shadow_rays(const BenchCamera& cam, const RaySet& primary, std::span<const Hit> hits);

// For each primary hit: a ray from p (tmin = 1e−4·R, tmax = inf) in a uniformly random direction
// on the hemisphere of the triangle's geometric normal cross(v1 − v0, v2 − v0), flipped to face
// the camera. Random numbers: splitmix64 seeded with the pixel index, two draws u1, u2 in [0, 1)
// (top 24 bits / 2^24); z = u1, φ = 2π·u2, dir = (√(1−z²)cos φ)·T + (√(1−z²)sin φ)·B + z·N, with
// T = normalize(cross(N, |N.x| > 0.5 ? (0,1,0) : (1,0,0))), B = cross(N, T).
RaySet incoherent_rays(const BenchCamera& cam, const TriangleMesh& mesh, const RaySet& primary,
                       std::span<const Hit> hits);

// Σ over hits of (pixel + 1)·(triangle id + 1) mod 2^64. Shadow rays have no id (any-hit): pass
// occluded flags and the sum is Σ (pixel + 1) over occluded rays.
uint64_t hit_checksum(const RaySet& set, std::span<const Hit> hits);
uint64_t occluded_checksum(const RaySet& set, std::span<const uint8_t> occluded);

}  // namespace rayvec
