// Lambert (1760): the ideal diffuse BRDF Kd/π.
#pragma once
#include <numbers>

#include "math/vec3.h"

namespace rayvec::shaders {

// Radiance reflected by a Lambertian surface of albedo `kd` under irradiance `irradiance`
// (already including cosθ): Kd/π · E. Inline: the integrator calls it for every lit light sample.
inline Vec3f lambert(Vec3f kd, Vec3f irradiance) { return kd * irradiance * std::numbers::inv_pi_v<float>; }

}  // namespace rayvec::shaders
