// SurfacePoint: what shading needs to know about a hit — position, normals, texture coordinates,
// material — in the orientation the shaders expect (normals facing the incoming ray).
#pragma once
#include "rays/ray.h"
#include "scene/scene.h"

namespace rayvec {

struct SurfacePoint {
  Vec3f p;             // from barycentrics: v0 + u·e1 + v·e2 (accurate to a few ulps of the vertices)
  Vec3f ng;            // unit geometric normal, flipped to face the incoming ray
  Vec3f ns;            // unit shading normal (interpolated vn, else ng), on the same side as ng
  bool entering;       // the ray arrives on the front (counter-clockwise, outward) side
  float u = 0, v = 0;  // texture coordinates (0 when the OBJ gives none)
  int32_t material = 0;
};

SurfacePoint surface_point(const Scene& scene, const Ray& ray, const Hit& hit);

// Diffuse albedo at the point: Kd, times the map_Kd texture (bilinear, repeating) when present.
Vec3f diffuse_albedo(const Scene& scene, const SurfacePoint& s);

}  // namespace rayvec
