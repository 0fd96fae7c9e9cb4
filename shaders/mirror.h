// Perfect specular reflection (Whitted 1980): the direction a mirror sends an incoming ray.
#pragma once
#include "math/vec3.h"

namespace rayvec::shaders {

// Reflects direction `d` (travelling toward the surface) about unit normal `n`: d − 2(d·n)n.
// Works for either orientation of n; |result| = |d|.
inline Vec3f mirror_direction(Vec3f d, Vec3f n) { return d - n * (2.0f * dot(d, n)); }

}  // namespace rayvec::shaders
