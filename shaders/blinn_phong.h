// Blinn (1977) specular highlight, normalized so that Ks is the fraction of light reflected into the
// lobe: BRDF Ks · (Ns + 8)/(8π) · (n·h)^Ns (Akenine-Möller et al., Real-Time Rendering, 4th ed., 9.8).
// The normalization keeps highlights from outshining the Kd/π diffuse term as Ns grows.
//
// Written in three steps — the half-vector cosine, the lobe, the radiance — so that the renderer can
// take a tile's cosines and radiances lane by lane and only the power one by one, with the very bits
// blinn_phong() gives (render/tile_lighting.h).
#pragma once
#include <cmath>
#include <numbers>

#include "math/vec3.h"

namespace rayvec::shaders {

// Whether Ks reflects anything: blinn_phong() is 0 when no channel of Ks is positive.
inline bool has_specular(Vec3f ks) { return !(ks.x <= 0 && ks.y <= 0 && ks.z <= 0); }

// cos θh = n·h/|h| for the half vector h of `to_light` and `to_eye` (unit vectors), 0 where |h| is
// 0 or NaN: the lobe exists only where it is > 0.
inline float blinn_phong_cos(Vec3f n, Vec3f to_light, Vec3f to_eye) {
  const Vec3f h = to_light + to_eye;
  const float len = length(h);
  const float cos_h = dot(n, h) / len;  // divided whatever len is, so a loop over lanes has no branch
  return len > 0 ? cos_h : 0.0f;
}

// The normalized lobe (Ns + 8)/(8π) · cos_h^Ns, for cos_h > 0.
inline float blinn_phong_lobe(float ns, float cos_h) {
  const float norm = (ns + 8.0f) / (8.0f * std::numbers::pi_v<float>);  // energy normalisation
  return norm * std::pow(cos_h, ns);
}

// Radiance toward `to_eye` from light arriving from `to_light` with irradiance `irradiance`
// (already including cosθ), for unit vectors n, to_light, to_eye on the same side. 0 when Ks = 0.
// Inline: the integrator calls it for every lit light sample of a highlighted material.
inline Vec3f blinn_phong(Vec3f ks, float ns, Vec3f n, Vec3f to_light, Vec3f to_eye, Vec3f irradiance) {
  if (!has_specular(ks)) return {};
  const float cos_h = blinn_phong_cos(n, to_light, to_eye);
  if (!(cos_h > 0)) return {};
  return ks * irradiance * blinn_phong_lobe(ns, cos_h);
}

}  // namespace rayvec::shaders
