// Blinn (1977) specular highlight, normalized so that Ks is the fraction of light reflected into the
// lobe: BRDF Ks · (Ns + 8)/(8π) · (n·h)^Ns (Akenine-Möller et al., Real-Time Rendering, 4th ed., 9.8).
// The normalization keeps highlights from outshining the Kd/π diffuse term as Ns grows.
#pragma once
#include "math/vec3.h"

namespace rayvec::shaders {

// Radiance toward `to_eye` from light arriving from `to_light` with irradiance `irradiance`
// (already including cosθ), for unit vectors n, to_light, to_eye on the same side. 0 when Ks = 0.
Vec3f blinn_phong(Vec3f ks, float ns, Vec3f n, Vec3f to_light, Vec3f to_eye, Vec3f irradiance);

}  // namespace rayvec::shaders
