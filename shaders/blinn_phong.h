// Blinn (1977) specular highlight, normalized so that Ks is the fraction of light reflected into the
// lobe: BRDF Ks · (Ns + 8)/(8π) · (n·h)^Ns (Akenine-Möller et al., Real-Time Rendering, 4th ed., 9.8).
// The normalization keeps highlights from outshining the Kd/π diffuse term as Ns grows.
#pragma once
#include <cmath>
#include <numbers>

#include "math/vec3.h"

namespace rayvec::shaders {

// Radiance toward `to_eye` from light arriving from `to_light` with irradiance `irradiance`
// (already including cosθ), for unit vectors n, to_light, to_eye on the same side. 0 when Ks = 0.
// Inline: the integrator calls it for every lit light sample of a highlighted material.
inline Vec3f blinn_phong(Vec3f ks, float ns, Vec3f n, Vec3f to_light, Vec3f to_eye, Vec3f irradiance) {
  if (ks.x <= 0 && ks.y <= 0 && ks.z <= 0) return {};
  const Vec3f h = to_light + to_eye;
  const float len = length(h);
  if (!(len > 0)) return {};
  const float cos_h = dot(n, h) / len;
  if (!(cos_h > 0)) return {};
  const float norm = (ns + 8.0f) / (8.0f * std::numbers::pi_v<float>);  // energy normalisation
  const float lobe = norm * std::pow(cos_h, ns);
  return ks * irradiance * lobe;
}

}  // namespace rayvec::shaders
