// PixelCost: the WhittedObserver behind the cost and bounces AOVs. Every ray the integrator traces
// for a pixel (camera, shadow, reflection, refraction) is traced once more through the
// accelerator's counting path (Accelerator::closest_counted / occluded_counted), adding the BVH
// nodes visited and the triangles tested; the deepest ray's depth is kept as the pixel's bounces.
// Only renders that ask for these AOVs pay for it.
#pragma once
#include "accel/accelerator.h"
#include "render/whitted_observer.h"

namespace rayvec {

class PixelCost final : public WhittedObserver {
 public:
  explicit PixelCost(const Accelerator& accel) : accel_(accel) {}

  void reset() {
    cost = {};
    bounces = 0;
  }

  void enter(RayKind, const Ray& ray, const Hit&, int depth, float, Vec3f) override {
    accel_.closest_counted(ray, cost);
    if (depth > bounces) bounces = depth;
  }
  void local(Vec3f) override {}
  void shadow(const Ray& ray, int, bool, Vec3f) override { accel_.occluded_counted(ray, cost); }
  void skipped(RayKind, SkipReason, float) override {}
  void leave(Vec3f) override {}

  TraversalCost cost;
  int bounces = 0;  // depth of the deepest ray since reset(): 0 = the camera ray only

 private:
  const Accelerator& accel_;
};

}  // namespace rayvec
