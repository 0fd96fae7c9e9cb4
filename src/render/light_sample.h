// What a light gives a surface point before any shadow: the direction to it, the irradiance through
// the shading normal's cosine, and whether it can light the point at all. One function per light
// type over plain values, branch-free, so that Whitted::direct_light (one hit at a time) and
// TileLighting (a tile's hits lane by lane) do the same arithmetic and get the same bits.
#pragma once
#include <cmath>

#include "rays/ray.h"
#include "scene/scene.h"

namespace rayvec {

// Just short of the light: an occluder exactly at the light's position does not shadow.
inline constexpr float kBeforeLight = 0.99999f;

struct LightSample {
  Vec3f to_light;    // unit direction from the point to the light
  Vec3f irradiance;  // at the point, times the cosine at the shading normal: what the BRDFs take
  bool faces;        // the light lies on the lit side of both normals: only then a shadow ray
};

// A light without power lights nothing and casts no shadow ray.
inline bool has_power(const Light& light) { return !(max_component(light.power) <= 0); }

// A point light of intensity I at `position`, seen from p: irradiance I/r². A light at p faces
// nothing.
inline LightSample point_light_sample(Vec3f position, Vec3f intensity, Vec3f p, Vec3f ng, Vec3f ns) {
  const Vec3f d = position - p;
  const float r2 = dot(d, d);
  const Vec3f to_light = d * (1.0f / std::sqrt(r2));
  const float cos_s = dot(ns, to_light);
  return {to_light, intensity * (1.0f / r2) * cos_s, bool((r2 > 0) & (dot(ng, to_light) > 0) & (cos_s > 0))};
}

// A directional light shining along `direction` (unit) with irradiance E.
inline LightSample directional_light_sample(Vec3f direction, Vec3f irradiance, Vec3f ng, Vec3f ns) {
  const Vec3f to_light = -direction;
  const float cos_s = dot(ns, to_light);
  return {to_light, irradiance * cos_s, bool((dot(ng, to_light) > 0) & (cos_s > 0))};
}

inline LightSample light_sample(const Light& light, Vec3f p, Vec3f ng, Vec3f ns) {
  return light.type == Light::Type::point ? point_light_sample(light.position, light.power, p, ng, ns)
                                          : directional_light_sample(light.direction, light.power, ng, ns);
}

// The shadow ray toward `light` from `origin` (offset_ray_origin of the point): a point light sits
// at t = 1, just beyond tmax.
inline Ray shadow_ray(const Light& light, Vec3f origin) {
  if (light.type == Light::Type::point) return Ray{origin, light.position - origin, 0.0f, kBeforeLight};
  return Ray{origin, -light.direction, 0.0f, kInf};
}

}  // namespace rayvec
