// The ray tree of one pixel sample: every ray the Whitted integrator traced for it (camera, shadow,
// reflection, refraction), what each hit, the weight it carried, what it added and why it stopped.
// Recorded through the integrator's observer hook (render/whitted_observer.h) while the sample is
// rendered exactly as render() renders it, so the tree is what made the pixel. `rayvec trace`
// prints it (render/ray_tree_format.h).
#pragma once
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "render/whitted_observer.h"
#include "scene/scene.h"

namespace rayvec {

struct SkippedRay {
  RayKind kind;
  SkipReason reason;
  float weight;  // what it would have carried
};

struct RayNode {
  RayKind kind = RayKind::camera;
  Ray ray;             // shadow rays toward a point light: unnormalised, the light at t = 1
  int depth = 0;       // shadow rays: the depth of the ray whose hit they light
  float weight = 1;    // the depth control's weight (max RGB of `throughput`)
  Vec3f factor{};      // RGB coefficient in the parent (kr, kt; 1 for the camera ray)
  Vec3f throughput{};  // product of the factors from the camera: how much of `local` reaches the pixel
  Hit hit;             // nearest hit (shadow rays: the nearest blocker, a miss when the light is reached)
  int32_t object = -1, material = -1;
  TraversalCost cost;  // the scalar single-ray traversal's work for this ray (bvh/counting_traversal.h)
  // camera, reflection and refraction rays
  Vec3f local{};     // the hit's local term (background on a miss)
  Vec3f radiance{};  // what the ray returned: local + factor-weighted children
  // shadow rays
  int light = -1;
  bool blocked = false;
  Vec3f lit{};  // what the light added to the local term (0 when blocked)
  std::vector<SkippedRay> skipped;
  std::vector<RayNode> children;  // in the order traced (shadow rays first)

  Vec3f contribution() const { return throughput * local; }  // to the pixel sample
  // Why the ray ends: "miss", "light_blocked", "light_reached", "unlit" (a constant-colour
  // material), "diffuse" (the material spawns no reflection or refraction), "continues" (a child
  // was traced) — then the skip reasons of its untraced children.
  std::vector<std::string> stop_reasons(const Scene& scene) const;
};

struct PixelTrace {
  int x = 0, y = 0, sample = 0, spp = 1;
  float px = 0, py = 0;  // the sample's image position
  RayNode root;          // the camera ray
  Vec3f sample_radiance{};
  Vec3f pixel{};  // the rendered pixel: all spp samples, averaged as render() does
  int max_depth = 0;
  float min_contribution = 0;
  RenderSettings::Effects effects;
};

// Renders pixel (x, y) as render() does under `settings` (every sample, for `pixel`) and records
// the tree of sample `sample` (0 <= sample < spp). x, y must lie inside the camera's image.
PixelTrace trace_pixel(const Scene& scene, const Accelerator& accel, const RenderSettings& settings, int x,
                       int y, int sample);

}  // namespace rayvec
