// The generated scene of `rayvec bench paper`: the sizes of Sena et al. (2018) Table 1 without their
// 3-D models (the paper does not publish them), so the same (rays, triangles) counts on a scene anyone
// can regenerate bit for bit. Deterministic on every platform: its own SplitMix64 generator and
// float arithmetic that does not depend on the standard library's distributions.
#pragma once
#include <cstdint>

#include "rays/ray.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {

// SplitMix64 (Steele, Lea & Flood 2014): tiny, fast, and the same sequence everywhere.
class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  uint64_t next();
  // Uniform in [0, 1) on the 2^-24 grid: the top 24 bits of next(), so exactly representable.
  float unit_float();

 private:
  uint64_t state_;
};

inline constexpr uint64_t kPaperSceneSeed = 0x5e4a2018;

// `count` triangles whose 3·count vertices are independent and uniform in the unit cube [0, 1)^3,
// drawn x, y, z for v0, then v1, then v2 of triangle 0, then triangle 1, ...
TriangleMesh paper_triangles(uint32_t count, uint64_t seed = kPaperSceneSeed);

// side × side primary rays of a pinhole camera at (0.5, 0.5, -1.5) looking along +z at the cube:
// pixel (i, j) (row j from the bottom) aims at the point ((i + 0.5)/side, (j + 0.5)/side, 0) on the
// cube's front face, so every ray enters the cube. Directions are normalized in double and rounded
// to float; tmin = 0, tmax = +inf. Ray index = j·side + i.
RayBatch paper_camera_rays(uint32_t side);

}  // namespace rayvec
