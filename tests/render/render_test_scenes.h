// Scenes built in code for the renderer tests (no files needed).
#pragma once
#include "scene/scene.h"

namespace rayvec::test {

// One huge triangle covering the plane y = 0 around the origin (a single triangle, so no shared
// edges), Lambertian with albedo kd, seen from straight above by a 64×48 camera.
inline Scene lambert_plane_scene(Vec3f kd) {
  Scene s;
  Material m;
  m.Kd = kd;
  m.illum = 1;
  const int32_t mat = s.add_material(m);
  s.add_triangle({-100, 0, 100}, {100, 0, 100}, {0, 0, -100}, mat);
  s.camera.eye = {0, 5, 0};
  s.camera.look_at = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.camera.fov_y = 60;
  s.camera.width = 64;
  s.camera.height = 48;
  return s;
}

}  // namespace rayvec::test
