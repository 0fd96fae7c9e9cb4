// Fresnel (1823) reflectance of a smooth dielectric boundary for unpolarized light: the mean of the
// s- and p-polarized reflectances, exact (not Schlick's approximation).
#pragma once
#include <algorithm>
#include <cmath>

namespace rayvec::shaders {

// cos_i: cosine of the incidence angle (> 0); n1: index on the incident side; n2: the other side.
// Returns 1 under total internal reflection. Inline and without a branch (the reflectance is
// formed either way and dropped under total internal reflection), so that a loop over hits runs in
// SIMD lanes with the bits of a call.
inline float fresnel_dielectric(float cos_i, float n1, float n2) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  const float sin_t = n1 / n2 * std::sqrt(std::max(0.0f, 1.0f - cos_i * cos_i));
  const float cos_t = std::sqrt(std::max(0.0f, 1.0f - sin_t * sin_t));
  const float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  const float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
  const float r = 0.5f * (rs * rs + rp * rp);
  return sin_t >= 1.0f ? 1.0f : r;
}

}  // namespace rayvec::shaders
