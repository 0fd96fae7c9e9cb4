// WhittedObserver: an onlooker the Whitted integrator tells about every ray it traces and every ray
// it decides not to trace. Normal renders pass none (a null pointer: one predictable branch per
// event); `rayvec trace` records the ray tree of one pixel through it (render/ray_tree.h) and the
// cost and bounces AOVs count each pixel's work through it (render/pixel_cost.h). The events nest:
// enter(camera) … [shadow …] [skipped …] [enter(child) … leave] … leave.
#pragma once
#include "math/vec3.h"
#include "rays/ray.h"

namespace rayvec {

enum class RayKind { camera, shadow, reflection, refraction };
const char* ray_kind_name(RayKind kind);  // "camera", "shadow", ...

// Why the integrator did not trace a child ray it could have.
enum class SkipReason {
  max_depth,                  // the child would be deeper than max_depth
  contribution_cutoff,        // its weight is below min_contribution (Hall & Greenberg 1983)
  total_internal_reflection,  // no refracted direction: the Fresnel reflection carries it all
  effect_off,                 // the effect is switched off (--effects)
};
const char* skip_reason_name(SkipReason reason);  // "max_depth", ...

class WhittedObserver {
 public:
  virtual ~WhittedObserver() = default;

  // A camera, reflection or refraction ray and its nearest hit, before the hit is shaded. `depth`
  // is 0 for the camera ray; `weight` is the ray's contribution to the pixel as the depth control
  // sees it (max RGB of the product of the coefficients above it); `factor` is the RGB coefficient
  // its radiance is multiplied by in its parent (kr or kt; 1 for the camera ray).
  virtual void enter(RayKind kind, const Ray& ray, const Hit& hit, int depth, float weight, Vec3f factor) = 0;
  // The local term of the current ray: background on a miss, else emission + ambient + direct light
  // (after the dissolve), before any reflected or refracted light is added.
  virtual void local(Vec3f radiance) = 0;
  // A shadow ray toward light `light` (index into Scene::lights) from the current hit; `lit` is
  // what that light added to the local term (zero when blocked).
  virtual void shadow(const Ray& ray, int light, bool blocked, Vec3f lit) = 0;
  // A reflection or refraction child of the current ray that is not traced, and the weight it
  // would have carried.
  virtual void skipped(RayKind kind, SkipReason reason, float weight) = 0;
  // The current ray is done: the radiance it returns to its parent (to the pixel for the camera ray).
  virtual void leave(Vec3f radiance) = 0;
};

}  // namespace rayvec
