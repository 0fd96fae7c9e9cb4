// Refraction through a smooth dielectric boundary (Snell's law), with total internal reflection.
#pragma once
#include <cmath>
#include <optional>

#include "math/vec3.h"

namespace rayvec::shaders {

// A refracted direction, or none (`ok` false: total internal reflection, `dir` meaningless).
struct Refraction {
  Vec3f dir;
  bool ok;
};

// Refracts unit direction `d` at a surface with unit normal `n` facing the incoming side
// (dot(d, n) < 0), going from a medium of index n1 into n2 (eta = n1/n2): the unit transmitted
// direction, or none under total internal reflection (sin²θt > 1). Without a branch (the direction
// is formed either way), so that a loop over hits runs in SIMD lanes.
inline Refraction refract(Vec3f d, Vec3f n, float eta) {
  const float cos_i = -dot(d, n);
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  const float cos_t = std::sqrt(1.0f - sin2_t);  // NaN under total internal reflection, not kept
  return {normalize(d * eta + n * (eta * cos_i - cos_t)), !(sin2_t > 1.0f)};
}

// refract() as an optional.
inline std::optional<Vec3f> refract_direction(Vec3f d, Vec3f n, float eta) {
  const Refraction r = refract(d, n, eta);
  if (!r.ok) return std::nullopt;
  return r.dir;
}

}  // namespace rayvec::shaders
