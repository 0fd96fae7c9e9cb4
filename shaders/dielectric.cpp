#include "shaders/dielectric.h"

#include <cmath>

namespace rayvec::shaders {

std::optional<Vec3f> refract_direction(Vec3f d, Vec3f n, float eta) {
  const float cos_i = -dot(d, n);
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  if (sin2_t > 1.0f) return std::nullopt;  // total internal reflection
  const float cos_t = std::sqrt(1.0f - sin2_t);
  return normalize(d * eta + n * (eta * cos_i - cos_t));
}

}  // namespace rayvec::shaders
