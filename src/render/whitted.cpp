#include "render/whitted.h"

#include <cmath>

#include "render/offset_ray.h"
#include "shaders/blinn_phong.h"
#include "shaders/dielectric.h"
#include "shaders/fresnel.h"
#include "shaders/lambert.h"
#include "shaders/mirror.h"
#include "shaders/shading_model.h"

namespace rayvec {
namespace {

// Just short of the light: an occluder exactly at the light's position does not shadow.
constexpr float kBeforeLight = 0.99999f;

}  // namespace

bool Whitted::child_worthwhile(int depth, float weight) const {
  return depth + 1 <= settings_.max_depth && weight >= settings_.min_contribution && weight > 0;
}

Vec3f Whitted::trace(RayKind kind, Vec3f factor, const Ray& ray, int depth, float weight,
                     RayCounts& rays) const {
  const Hit hit = accel_.closest(ray);
  if (observer_) return shade_observed(kind, factor, ray, hit, depth, weight, rays);
  return shade_hit(ray, hit, depth, weight, rays);
}

void Whitted::skip(RayKind kind, int depth, float weight) const {
  if (!observer_) return;
  observer_->skipped(
      kind, depth + 1 > settings_.max_depth ? SkipReason::max_depth : SkipReason::contribution_cutoff,
      weight);
}

Vec3f Whitted::shade(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays) const {
  if (observer_) return shade_observed(RayKind::camera, Vec3f{1, 1, 1}, ray, hit, depth, weight, rays);
  return shade_hit(ray, hit, depth, weight, rays);
}

Vec3f Whitted::shade_observed(RayKind kind, Vec3f factor, const Ray& ray, const Hit& hit, int depth,
                              float weight, RayCounts& rays) const {
  observer_->enter(kind, ray, hit, depth, weight, factor);
  const Vec3f radiance = shade_hit(ray, hit, depth, weight, rays);
  observer_->leave(radiance);
  return radiance;
}

void Whitted::light_sample(const SurfacePoint& s, Vec3f origin, const Light& light, LightSample& l) const {
  // Computed in locals and stored once: a field read back right after its stores (the shadow ray's
  // direction from to_light) would wait on store forwarding.
  l.faces = false;
  if (max_component(light.power) <= 0) return;
  Vec3f to_light, irradiance, shadow_dir;
  float tmax = kInf;
  if (light.type == Light::Type::point) {
    const Vec3f d = light.position - s.p;
    const float r2 = dot(d, d);
    if (!(r2 > 0)) return;
    to_light = d * (1.0f / std::sqrt(r2));
    irradiance = light.power * (1.0f / r2);  // I / r²
    shadow_dir = light.position - origin;    // the light sits at t = 1
    tmax = kBeforeLight;
  } else {
    to_light = -light.direction;
    irradiance = light.power;
    shadow_dir = to_light;
  }
  // Only lights on the lit side of both normals can contribute: no shadow ray otherwise.
  const float cos_s = dot(s.ns, to_light);
  l = LightSample{to_light, irradiance, cos_s, Ray{origin, shadow_dir, 0.0f, tmax},
                  dot(s.ng, to_light) > 0 && cos_s > 0};
}

Vec3f Whitted::direct_light(const SurfacePoint& s, const Material& m, Vec3f kd, Vec3f to_eye, RayCounts& rays,
                            const Precomputed* lit) const {
  Vec3f sum{};
  const bool highlight = shaders::has_highlight(shaders::shading_model(m));
  const Vec3f origin = lit ? Vec3f{} : offset_ray_origin(s.p, s.ng);
  LightSample computed;
  for (std::size_t li = 0; li < scene_.lights.size(); ++li) {
    if (!lit) light_sample(s, origin, scene_.lights[li], computed);
    const LightSample& l = lit ? lit->samples[li] : computed;
    if (!l.faces) continue;
    if (settings_.effects.shadows) {
      ++rays.shadow;
      const bool blocked = lit ? lit->blocked[li] != 0 : accel_.occluded(l.shadow);
      if (observer_ && blocked) observer_->shadow(l.shadow, int(li), true, Vec3f{});
      if (blocked) continue;
    }
    const Vec3f e = l.irradiance * l.cos_s;
    Vec3f light = shaders::lambert(kd, e);
    if (highlight) light += shaders::blinn_phong(m.Ks, m.Ns, s.ns, l.to_light, to_eye, e);
    sum += light;
    if (observer_ && settings_.effects.shadows) observer_->shadow(l.shadow, int(li), false, light);
  }
  return sum;
}

bool Whitted::lit_surface(const Ray& ray, const Hit& hit, SurfacePoint& s) const {
  if (!hit.hit()) return false;
  surface_point(scene_, ray, hit, normals_, s);
  // The material from the scene, not s.material: that field was stored a moment ago.
  return shaders::is_lit(shaders::shading_model(scene_.materials[scene_.triangle_material[hit.tri]]));
}

void Whitted::light_samples(const SurfacePoint& s, LightSample* out) const {
  const Vec3f origin = offset_ray_origin(s.p, s.ng);
  for (std::size_t li = 0; li < scene_.lights.size(); ++li)
    light_sample(s, origin, scene_.lights[li], out[li]);
}

Vec3f Whitted::shade_primary(const Ray& ray, const Hit& hit, const SurfacePoint& s,
                             const LightSample* samples, const uint8_t* blocked, RayCounts& rays) const {
  const Precomputed lit{s, samples, blocked};
  if (!observer_) return shade_hit(ray, hit, 0, 1.0f, rays, &lit);
  observer_->enter(RayKind::camera, ray, hit, 0, 1.0f, Vec3f{1, 1, 1});
  const Vec3f radiance = shade_hit(ray, hit, 0, 1.0f, rays, &lit);
  observer_->leave(radiance);
  return radiance;
}

Vec3f Whitted::shade_hit(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays,
                         const Precomputed* lit) const {
  if (!hit.hit()) {
    if (observer_) observer_->local(scene_.background);
    return scene_.background;
  }
  SurfacePoint computed;
  if (!lit) surface_point(scene_, ray, hit, normals_, computed);
  const SurfacePoint& s = lit ? lit->s : computed;
  const Material& m = scene_.materials[s.material];
  const shaders::ShadingModel model = shaders::shading_model(m);
  const Vec3f kd = diffuse_albedo(scene_, s);
  if (!shaders::is_lit(model)) {  // constant colour, no lighting
    if (observer_) observer_->local(m.Ke + kd);
    return m.Ke + kd;
  }

  const Vec3f dir = normalize(ray.dir);
  Vec3f radiance = m.Ka * scene_.ambient + direct_light(s, m, kd, -dir, rays, lit);
  if (shaders::refracts(m)) radiance *= m.d;  // dissolve: the local term's opacity over the refraction
  radiance += m.Ke;
  if (observer_) observer_->local(radiance);

  // Fresnel reflectance for the Fresnel models: n1 on the incoming side, n2 beyond.
  const float n1 = s.entering ? 1.0f : m.Ni, n2 = s.entering ? m.Ni : 1.0f;
  const float fresnel =
      shaders::uses_fresnel(model) ? shaders::fresnel_dielectric(-dot(dir, s.ns), n1, n2) : 1.0f;

  if (shaders::reflects(m)) {
    const Vec3f kr = shaders::reflection_weight(m, fresnel);
    const float w = weight * max_component(kr);
    if (!settings_.effects.reflection) {
      if (observer_) observer_->skipped(RayKind::reflection, SkipReason::effect_off, w);
    } else if (child_worthwhile(depth, w)) {
      Vec3f r = shaders::mirror_direction(dir, s.ns);
      if (!(dot(r, s.ng) > 0)) r = shaders::mirror_direction(dir, s.ng);  // shading normal too bent
      ++rays.reflection;
      radiance += kr * trace(RayKind::reflection, kr, Ray{offset_ray_origin(s.p, s.ng), r, 0.0f, kInf},
                             depth + 1, w, rays);
    } else {
      skip(RayKind::reflection, depth, w);
    }
  }
  if (shaders::refracts(m)) {
    const Vec3f kt = shaders::transmission_weight(m, fresnel);
    const float w = weight * max_component(kt);
    if (!settings_.effects.refraction) {
      if (observer_) observer_->skipped(RayKind::refraction, SkipReason::effect_off, w);
    } else if (child_worthwhile(depth, w)) {
      std::optional<Vec3f> t = shaders::refract_direction(dir, s.ns, n1 / n2);
      if (t && !(dot(*t, s.ng) < 0)) t = shaders::refract_direction(dir, s.ng, n1 / n2);
      if (t) {  // none under total internal reflection: the Fresnel reflection carries it all
        ++rays.refraction;
        radiance += kt * trace(RayKind::refraction, kt, Ray{offset_ray_origin(s.p, -s.ng), *t, 0.0f, kInf},
                               depth + 1, w, rays);
      } else if (observer_) {
        observer_->skipped(RayKind::refraction, SkipReason::total_internal_reflection, w);
      }
    } else if (observer_) {
      // Beyond the critical angle the Fresnel reflectance is 1, so the refraction weighs 0: name
      // the cause, not the cutoff.
      const bool tir = !shaders::refract_direction(dir, s.ns, n1 / n2);
      if (tir && depth + 1 <= settings_.max_depth)
        observer_->skipped(RayKind::refraction, SkipReason::total_internal_reflection, w);
      else
        skip(RayKind::refraction, depth, w);
    }
  }
  return radiance;
}

}  // namespace rayvec
