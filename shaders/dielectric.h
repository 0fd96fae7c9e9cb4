// Refraction through a smooth dielectric boundary (Snell's law), with total internal reflection.
#pragma once
#include <optional>

#include "math/vec3.h"

namespace rayvec::shaders {

// Refracts unit direction `d` at a surface with unit normal `n` facing the incoming side
// (dot(d, n) < 0), going from a medium of index n1 into n2 (eta = n1/n2). Returns the unit
// transmitted direction, or nullopt under total internal reflection (sin²θt > 1).
std::optional<Vec3f> refract_direction(Vec3f d, Vec3f n, float eta);

}  // namespace rayvec::shaders
