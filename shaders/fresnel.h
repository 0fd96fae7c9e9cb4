// Fresnel (1823) reflectance of a smooth dielectric boundary for unpolarized light: the mean of the
// s- and p-polarized reflectances, exact (not Schlick's approximation).
#pragma once

namespace rayvec::shaders {

// cos_i: cosine of the incidence angle (> 0); n1: index on the incident side; n2: the other side.
// Returns 1 under total internal reflection.
float fresnel_dielectric(float cos_i, float n1, float n2);

}  // namespace rayvec::shaders
