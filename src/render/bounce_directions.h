// The directions and the Fresnel reflectance a hit's bounce needs (Whitted::bounce): the incoming
// direction at unit length, the mirror direction, the refracted one, each falling back to the
// geometric normal where the shading normal bends it to the wrong side. Branch-free — both
// children's directions are formed whatever the material spawns — so that a loop over a
// generation's hits runs in SIMD lanes (render/tile_waves.cpp) and gives the one-hit bits.
#pragma once
#include "math/vec3.h"
#include "shaders/dielectric.h"
#include "shaders/fresnel.h"
#include "shaders/mirror.h"

namespace rayvec {

struct BounceDirections {
  Vec3f dir;        // the incoming ray's direction, unit length
  float fresnel;    // Fresnel reflectance at the hit; 1 where the model has no Fresnel term
  Vec3f mirror;     // the mirror ray's direction
  Vec3f refracted;  // the refraction ray's direction, where `refracts`
  bool refracts;    // false under total internal reflection
};

// For a ray of direction ray_dir reaching a hit with shading normal ns and geometric normal ng
// (both facing the ray), from outside (`entering`) or inside a material of index `ni`, whose model
// weighs its children by the Fresnel equations or not (`fresnel_model`).
inline BounceDirections bounce_directions(Vec3f ray_dir, Vec3f ns, Vec3f ng, bool entering, float ni,
                                          bool fresnel_model) {
  BounceDirections b;
  b.dir = normalize(ray_dir);
  // n1 on the incoming side, n2 beyond
  const float n1 = entering ? 1.0f : ni, n2 = entering ? ni : 1.0f;
  const float f = shaders::fresnel_dielectric(-dot(b.dir, ns), n1, n2);
  b.fresnel = fresnel_model ? f : 1.0f;
  const Vec3f r = shaders::mirror_direction(b.dir, ns);
  const Vec3f r_ng = shaders::mirror_direction(b.dir, ng);
  const bool r_bent = !(dot(r, ng) > 0);  // the shading normal too bent: mirror about ng
  b.mirror = {r_bent ? r_ng.x : r.x, r_bent ? r_ng.y : r.y, r_bent ? r_ng.z : r.z};
  const shaders::Refraction t = shaders::refract(b.dir, ns, n1 / n2);
  const shaders::Refraction t_ng = shaders::refract(b.dir, ng, n1 / n2);
  const bool t_back = !(dot(t.dir, ng) < 0);  // refracted back to the incoming side: about ng
  const bool t_bent = t.ok & t_back;
  b.refracted = {t_bent ? t_ng.dir.x : t.dir.x, t_bent ? t_ng.dir.y : t.dir.y, t_bent ? t_ng.dir.z : t.dir.z};
  b.refracts = t.ok & (!t_back | t_ng.ok);  // bit operations, not a select of bools: lanes
  return b;
}

}  // namespace rayvec
