#include "render/tile_waves.h"

namespace rayvec {

TileWaves::TileWaves(const Scene& scene, const Accelerator& accel, const Whitted& whitted,
                     std::size_t max_wave_rays)
    : scene_(scene),
      accel_(accel),
      whitted_(whitted),
      max_wave_rays_(max_wave_rays),
      lighting_(scene, accel, whitted) {}

void TileWaves::expand(const Ray& ray, const Hit& hit, const TileLighting& lighting, int j, int depth,
                       float weight, Node& node, RayCounts& counts) {
  if (!lighting.lit(j)) {  // a miss or an unlit material: shade() spawns nothing there
    node.radiance = whitted_.shade(ray, hit, depth, weight, counts);
    return;
  }
  if (lighting.finished(j)) {
    node.radiance = lighting.radiance(j);
    return;
  }
  const Whitted::Bounce b = whitted_.bounce(ray, lighting.surface(j), lighting.direct(j), depth, weight);
  if (reflections_.rays.size() + refractions_.rays.size() + 2 > max_wave_rays_) {
    node.radiance = whitted_.finish(b, depth, counts);  // a full generation: this tree one ray at a time
    return;
  }
  node.radiance = b.local;
  if (b.reflection.state == Whitted::Child::traced) {
    node.kr = b.reflection.k;
    node.reflection = int32_t(reflections_.rays.size());
    reflections_.rays.push_back(b.reflection.ray);
    reflections_.weights.push_back(b.reflection.weight);
    ++counts.reflection;
  }
  if (b.refraction.state == Whitted::Child::traced) {
    node.kt = b.refraction.k;
    node.refraction = int32_t(refractions_.rays.size());  // moved past the reflections below
    refractions_.rays.push_back(b.refraction.ray);
    refractions_.weights.push_back(b.refraction.weight);
    ++counts.refraction;
  }
}

void TileWaves::shade(const Ray* rays, const Hit* hits, int n, const TileLighting& camera, Vec3f* out,
                      RayCounts& counts) {
  // generation 0: the camera hits that spawn a ray (lit, not finished); the others are the caller's
  roots_.clear();
  for (int j = 0; j < n; ++j)
    if (camera.lit(j) && !camera.finished(j)) roots_.push_back(j);
  if (roots_.empty()) return;
  int depth = 0;
  for (;;) {
    if (nodes_.size() <= std::size_t(depth)) nodes_.emplace_back();
    std::vector<Node>& nodes = nodes_[std::size_t(depth)];
    const bool first = depth == 0;
    const int m = int(first ? roots_.size() : rays_.size());
    nodes.assign(std::size_t(m), Node{});
    reflections_.clear();
    refractions_.clear();
    for (int j = 0; j < m; ++j) {
      if (first) {
        const int r = roots_[std::size_t(j)];
        expand(rays[r], hits[r], camera, r, 0, 1.0f, nodes[std::size_t(j)], counts);
      } else {
        expand(rays_[std::size_t(j)], hits_[std::size_t(j)], lighting_, j, depth, weights_[std::size_t(j)],
               nodes[std::size_t(j)], counts);
      }
    }
    // the next generation: the reflections, then the refractions
    const int32_t reflected = int32_t(reflections_.rays.size());
    for (Node& node : nodes)
      if (node.refraction >= 0) node.refraction += reflected;
    rays_.assign(reflections_.rays.begin(), reflections_.rays.end());
    rays_.insert(rays_.end(), refractions_.rays.begin(), refractions_.rays.end());
    weights_.assign(reflections_.weights.begin(), reflections_.weights.end());
    weights_.insert(weights_.end(), refractions_.weights.begin(), refractions_.weights.end());
    if (rays_.empty()) break;
    ++depth;
    hits_.resize(rays_.size());
    // packets whatever the rays' spread: a packet's lanes that part ways finish by single-ray
    // traversal, and that beat tracing the groups whose directions disagree ray by ray
    accel_.closest_stream(rays_.data(), hits_.data(), rays_.size());
    lighting_.light(rays_.data(), hits_.data(), int(rays_.size()));
    counts.shadow += lighting_.shadow_rays();
  }
  // each hit's children into its radiance, deepest generation first
  for (int d = depth - 1; d >= 0; --d) {
    const std::vector<Node>& below = nodes_[std::size_t(d) + 1];
    for (Node& node : nodes_[std::size_t(d)]) {
      if (node.reflection >= 0) node.radiance += node.kr * below[std::size_t(node.reflection)].radiance;
      if (node.refraction >= 0) node.radiance += node.kt * below[std::size_t(node.refraction)].radiance;
    }
  }
  for (std::size_t k = 0; k < roots_.size(); ++k) out[roots_[k]] = nodes_[0][k].radiance;
}

}  // namespace rayvec
