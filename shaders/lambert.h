// Lambert (1760): the ideal diffuse BRDF Kd/π.
#pragma once
#include "math/vec3.h"

namespace rayvec::shaders {

// Radiance reflected by a Lambertian surface of albedo `kd` under irradiance `irradiance`
// (already including cosθ): Kd/π · E.
Vec3f lambert(Vec3f kd, Vec3f irradiance);

}  // namespace rayvec::shaders
