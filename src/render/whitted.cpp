#include "render/whitted.h"

#include <cmath>

#include "render/light_sample.h"
#include "render/offset_ray.h"
#include "shaders/blinn_phong.h"
#include "shaders/dielectric.h"
#include "shaders/fresnel.h"
#include "shaders/lambert.h"
#include "shaders/mirror.h"
#include "shaders/shading_model.h"

namespace rayvec {
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

Vec3f Whitted::direct_light(const SurfacePoint& s, const Material& m, Vec3f kd, Vec3f to_eye,
                            RayCounts& rays) const {
  Vec3f sum{};
  const bool highlight = shaders::has_highlight(shaders::shading_model(m));
  const Vec3f origin = offset_ray_origin(s.p, s.ng);
  for (std::size_t li = 0; li < scene_.lights.size(); ++li) {
    const Light& light = scene_.lights[li];
    if (!has_power(light)) continue;
    const LightSample l = light_sample(light, s.p, s.ng, s.ns);
    if (!l.faces) continue;  // only lights on the lit side of both normals: no shadow ray otherwise
    const bool shadows = settings_.effects.shadows;
    const Ray shadow = shadows ? shadow_ray(light, origin) : Ray{};
    if (shadows) {
      ++rays.shadow;
      const bool blocked = accel_.occluded(shadow);
      if (observer_ && blocked) observer_->shadow(shadow, int(li), true, Vec3f{});
      if (blocked) continue;
    }
    Vec3f lit = shaders::lambert(kd, l.irradiance);
    if (highlight) lit += shaders::blinn_phong(m.Ks, m.Ns, s.ns, l.to_light, to_eye, l.irradiance);
    sum += lit;
    if (observer_ && shadows) observer_->shadow(shadow, int(li), false, lit);
  }
  return sum;
}

bool Whitted::lit_surface(const Ray& ray, const Hit& hit, SurfacePoint& s) const {
  if (!hit.hit()) return false;
  surface_point(scene_, ray, hit, normals_, s);
  // The material from the scene, not s.material: that field was stored a moment ago.
  return shaders::is_lit(shaders::shading_model(scene_.materials[scene_.triangle_material[hit.tri]]));
}

Vec3f Whitted::shade_primary(const Ray& ray, const Hit& hit, const SurfacePoint& s, Vec3f direct,
                             RayCounts& rays) const {
  const Precomputed lit{s, direct};
  return shade_hit(ray, hit, 0, 1.0f, rays, &lit);
}

bool Whitted::local_only(const Material& m) { return !shaders::reflects(m) && !shaders::refracts(m); }

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
  if (!shaders::is_lit(model)) {  // constant colour, no lighting
    const Vec3f kd = diffuse_albedo(scene_, s);
    if (observer_) observer_->local(m.Ke + kd);
    return m.Ke + kd;
  }

  const Vec3f dir = normalize(ray.dir);
  Vec3f direct;
  if (lit)
    direct = lit->direct;
  else
    direct = direct_light(s, m, diffuse_albedo(scene_, s), -dir, rays);
  // TileLighting takes this sum for a local_only material: the same steps there
  Vec3f radiance = m.Ka * scene_.ambient + direct;
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
