#include "render/tile_waves.h"

#include "shaders/shading_model.h"

namespace rayvec {

TileWaves::TileWaves(const Scene& scene, const Accelerator& accel, const Whitted& whitted,
                     std::size_t max_wave_rays)
    : accel_(accel), whitted_(whitted), max_wave_rays_(max_wave_rays), lighting_(scene, accel, whitted) {
  for (const Material& m : scene.materials) {
    ni_.push_back(m.Ni);
    fresnel_model_.push_back(shaders::uses_fresnel(m));
  }
}

namespace {

void directions_lanes(Lanes3In ray_dir, Lanes3In ns, Lanes3In ng, const int32_t* __restrict entering,
                      const float* __restrict ni, const int32_t* __restrict fresnel_model, Lanes3Out dir,
                      Lanes3Out mirror, Lanes3Out refracted, float* __restrict fresnel,
                      int32_t* __restrict refracts, int m) {
  for (int k = 0; k < m; ++k) {
    const BounceDirections b =
        bounce_directions(ray_dir[k], ns[k], ng[k], entering[k] != 0, ni[k], fresnel_model[k] != 0);
    dir.set(k, b.dir);
    mirror.set(k, b.mirror);
    refracted.set(k, b.refracted);
    fresnel[k] = b.fresnel;
    refracts[k] = b.refracts;
  }
}

}  // namespace

void TileWaves::directions(const Ray* rays, const int* index, const TileLighting& lighting, int m) {
  const std::size_t n = std::size_t(m);
  for (Vec3Lanes* v : {&ray_dir_, &ns_, &ng_, &dir_, &mirror_, &refracted_}) v->resize(n);
  for (auto* v : {&entering_, &node_fresnel_model_, &refracts_}) v->resize(n);
  node_ni_.resize(n);
  fresnel_.resize(n);
  for (int k = 0; k < m; ++k) {
    const int j = index ? index[k] : k;
    Vec3f d{0, 0, -1}, ns{0, 0, 1}, ng{0, 0, 1};  // a placeholder for the nodes that spawn nothing
    bool entering = true;
    float ni = 1.0f;
    int32_t fresnel_model = 0;
    if (lighting.lit(j) && !lighting.finished(j)) {
      const SurfacePoint& s = lighting.surface(j);
      d = rays[j].dir;
      ns = s.ns;
      ng = s.ng;
      entering = s.entering;
      ni = ni_[std::size_t(s.material)];
      fresnel_model = fresnel_model_[std::size_t(s.material)];
    }
    ray_dir_.set(std::size_t(k), d);
    ns_.set(std::size_t(k), ns);
    ng_.set(std::size_t(k), ng);
    entering_[k] = entering;
    node_ni_[k] = ni;
    node_fresnel_model_[k] = fresnel_model;
  }
  directions_lanes(in(ray_dir_), in(ns_), in(ng_), entering_.data(), node_ni_.data(),
                   node_fresnel_model_.data(), out(dir_), out(mirror_), out(refracted_), fresnel_.data(),
                   refracts_.data(), m);
}

BounceDirections TileWaves::direction(int k) const {
  const std::size_t i = std::size_t(k);
  return {dir_[i], fresnel_[i], mirror_[i], refracted_[i], refracts_[i] != 0};
}

void TileWaves::expand(const Ray& ray, const Hit& hit, const TileLighting& lighting, int j, int k, int depth,
                       float weight, Node& node, RayCounts& counts) {
  if (!lighting.lit(j)) {  // a miss or an unlit material: shade() spawns nothing there
    node.radiance = whitted_.shade(ray, hit, depth, weight, counts);
    return;
  }
  if (lighting.finished(j)) {
    node.radiance = lighting.radiance(j);
    return;
  }
  const Whitted::Bounce b =
      whitted_.bounce(lighting.surface(j), lighting.direct(j), depth, weight, direction(k));
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
    if (first)
      directions(rays, roots_.data(), camera, m);
    else
      directions(rays_.data(), nullptr, lighting_, m);
    for (int j = 0; j < m; ++j) {
      if (first) {
        const int r = roots_[std::size_t(j)];
        expand(rays[r], hits[r], camera, r, j, 0, 1.0f, nodes[std::size_t(j)], counts);
      } else {
        expand(rays_[std::size_t(j)], hits_[std::size_t(j)], lighting_, j, j, depth, weights_[std::size_t(j)],
               nodes[std::size_t(j)], counts);
      }
    }
    // the next generation: the reflections, then the refractions
    const int32_t reflected = int32_t(reflections_.rays.size());
    for (Node& node : nodes)
      if (node.refraction >= 0) node.refraction += reflected;
    rays_.swap(reflections_.rays);  // the generation just expanded goes; cleared before the next one
    rays_.insert(rays_.end(), refractions_.rays.begin(), refractions_.rays.end());
    weights_.swap(reflections_.weights);
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
