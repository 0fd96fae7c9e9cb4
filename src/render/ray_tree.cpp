#include "render/ray_tree.h"

#include <algorithm>

#include "render/camera_rays.h"
#include "render/pixel_samples.h"
#include "render/renderer.h"
#include "render/whitted.h"
#include "shaders/shading_model.h"

namespace rayvec {
namespace {

// Builds the tree from the observer's events: a stack of the rays being shaded. A parent's
// children vector only grows while none of its earlier children is on the stack, so the pointers
// held are stable.
class RayTreeRecorder final : public WhittedObserver {
 public:
  RayTreeRecorder(const Scene& scene, const Accelerator& accel, RayNode& root)
      : scene_(scene), accel_(accel), root_(root) {}

  void enter(RayKind kind, const Ray& ray, const Hit& hit, int depth, float weight, Vec3f factor) override {
    RayNode* node = &root_;
    if (!stack_.empty()) node = &stack_.back()->children.emplace_back();
    node->kind = kind;
    node->ray = ray;
    node->depth = depth;
    node->weight = weight;
    node->factor = factor;
    node->throughput = stack_.empty() ? factor : stack_.back()->throughput * factor;
    node->hit = hit;
    describe_hit(*node);
    accel_.closest_counted(ray, node->cost);
    stack_.push_back(node);
  }
  void local(Vec3f radiance) override { stack_.back()->local = radiance; }
  void shadow(const Ray& ray, int light, bool blocked, Vec3f lit) override {
    RayNode& parent = *stack_.back();
    RayNode& node = parent.children.emplace_back();
    node.kind = RayKind::shadow;
    node.ray = ray;
    node.depth = parent.depth;
    node.weight = parent.weight;
    node.factor = Vec3f{1, 1, 1};
    node.throughput = parent.throughput;
    node.light = light;
    node.blocked = blocked;
    node.lit = lit;
    accel_.occluded_counted(ray, node.cost);
    if (blocked) node.hit = accel_.closest(ray);  // the nearest blocker, for the reader
    describe_hit(node);
  }
  void skipped(RayKind kind, SkipReason reason, float weight) override {
    stack_.back()->skipped.push_back({kind, reason, weight});
  }
  void leave(Vec3f radiance) override {
    stack_.back()->radiance = radiance;
    stack_.pop_back();
  }

 private:
  void describe_hit(RayNode& node) const {
    if (!node.hit.hit()) return;
    node.object = scene_.triangle_object[node.hit.tri];
    node.material = scene_.triangle_material[node.hit.tri];
  }

  const Scene& scene_;
  const Accelerator& accel_;
  RayNode& root_;
  std::vector<RayNode*> stack_;
};

}  // namespace

std::vector<std::string> RayNode::stop_reasons(const Scene& scene) const {
  std::vector<std::string> why;
  if (kind == RayKind::shadow) {
    why.push_back(blocked ? "light_blocked" : "light_reached");
    return why;
  }
  if (!hit.hit()) {
    why.push_back("miss");
    return why;
  }
  const Material& m = scene.materials[material];
  const bool traced = std::any_of(children.begin(), children.end(),
                                  [](const RayNode& c) { return c.kind != RayKind::shadow; });
  if (!shaders::is_lit(shaders::shading_model(m)))
    why.push_back("unlit");
  else if (traced)
    why.push_back("continues");
  else if (skipped.empty())
    why.push_back("diffuse");
  for (const SkippedRay& s : skipped) why.push_back(skip_reason_name(s.reason));
  return why;
}

PixelTrace trace_pixel(const Scene& scene, const Accelerator& accel, const RenderSettings& settings, int x,
                       int y, int sample) {
  PixelTrace out;
  out.x = x;
  out.y = y;
  out.sample = sample;
  out.spp = std::max(1, settings.spp);
  out.max_depth = settings.max_depth;
  out.min_contribution = settings.min_contribution;
  out.effects = settings.effects;
  const CameraRays camera(scene.camera);
  RayTreeRecorder recorder(scene, accel, out.root);
  const Whitted plain(scene, accel, settings), recording(scene, accel, settings, &recorder);
  RayCounts rays;
  // The same arithmetic as render(): samples summed in order from zero, then scaled by 1/spp.
  Vec3f sum{};
  for (int s = 0; s < out.spp; ++s) {
    const auto [sx, sy] = sample_position(x, y, s, out.spp);
    const Ray ray = camera.ray(float(x) + sx, float(y) + sy);
    const Hit hit = accel.closest(ray);  // what closest_stream gives ray by ray
    const Whitted& whitted = s == sample ? recording : plain;
    const Vec3f radiance = whitted.shade(ray, hit, 0, 1.0f, rays);
    if (s == sample) {
      out.px = float(x) + sx;
      out.py = float(y) + sy;
      out.sample_radiance = radiance;
    }
    sum += radiance;
  }
  out.pixel = sum * (1.0f / float(out.spp));
  return out;
}

}  // namespace rayvec
