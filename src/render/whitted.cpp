#include "render/whitted.h"

#include <cmath>

#include "render/bounce_directions.h"
#include "render/light_sample.h"
#include "render/offset_ray.h"
#include "shaders/blinn_phong.h"
#include "shaders/dielectric.h"
#include "shaders/lambert.h"
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

bool Whitted::local_only(const Material& m) { return !shaders::reflects(m) && !shaders::refracts(m); }

Whitted::Bounce Whitted::bounce(const Ray& ray, const SurfacePoint& s, Vec3f direct, int depth,
                                float weight) const {
  const Material& m = scene_.materials[s.material];
  return bounce(s, direct, depth, weight,
                bounce_directions(ray.dir, s.ns, s.ng, s.entering, m.Ni, shaders::uses_fresnel(m)));
}

Whitted::Bounce Whitted::bounce(const SurfacePoint& s, Vec3f direct, int depth, float weight,
                                const BounceDirections& g) const {
  const Material& m = scene_.materials[s.material];
  Bounce b;
  // TileLighting takes this sum for a local_only material: the same steps there
  b.local = m.Ka * scene_.ambient + direct;
  if (shaders::refracts(m)) b.local *= m.d;  // dissolve: the local term's opacity over the refraction
  b.local += m.Ke;

  if (shaders::reflects(m)) {
    ChildRay& c = b.reflection;
    c.k = shaders::reflection_weight(m, g.fresnel);
    c.weight = weight * max_component(c.k);
    if (!settings_.effects.reflection) {
      c.state = Child::effect_off;
    } else if (child_worthwhile(depth, c.weight)) {
      c.state = Child::traced;
      c.ray = Ray{offset_ray_origin(s.p, s.ng), g.mirror, 0.0f, kInf};
    } else {
      c.state = Child::cutoff;
    }
  }
  if (shaders::refracts(m)) {
    ChildRay& c = b.refraction;
    c.k = shaders::transmission_weight(m, g.fresnel);
    c.weight = weight * max_component(c.k);
    if (!settings_.effects.refraction) {
      c.state = Child::effect_off;
    } else if (child_worthwhile(depth, c.weight)) {
      if (g.refracts) {
        c.state = Child::traced;
        c.ray = Ray{offset_ray_origin(s.p, -s.ng), g.refracted, 0.0f, kInf};
      } else {  // no refracted direction: the Fresnel reflection carries it all
        c.state = Child::total_internal_reflection;
      }
    } else {
      c.state = Child::cutoff;
      // Beyond the critical angle the Fresnel reflectance is 1, so the refraction weighs 0: an
      // observer is told the cause, not the cutoff.
      const float eta = s.entering ? 1.0f / m.Ni : m.Ni;
      if (observer_ && depth + 1 <= settings_.max_depth && !shaders::refract(g.dir, s.ns, eta).ok)
        c.state = Child::total_internal_reflection;
    }
  }
  return b;
}

void Whitted::follow(RayKind kind, const ChildRay& c, int depth, Vec3f& radiance, RayCounts& rays) const {
  switch (c.state) {
    case Child::none: break;
    case Child::traced:
      ++(kind == RayKind::reflection ? rays.reflection : rays.refraction);
      radiance += c.k * trace(kind, c.k, c.ray, depth + 1, c.weight, rays);
      break;
    case Child::effect_off:
      if (observer_) observer_->skipped(kind, SkipReason::effect_off, c.weight);
      break;
    case Child::cutoff: skip(kind, depth, c.weight); break;
    case Child::total_internal_reflection:
      if (observer_) observer_->skipped(kind, SkipReason::total_internal_reflection, c.weight);
      break;
  }
}

Vec3f Whitted::shade_hit(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays) const {
  if (!hit.hit()) {
    if (observer_) observer_->local(scene_.background);
    return scene_.background;
  }
  SurfacePoint s;
  surface_point(scene_, ray, hit, normals_, s);
  const Material& m = scene_.materials[s.material];
  if (!shaders::is_lit(shaders::shading_model(m))) {  // constant colour, no lighting
    const Vec3f kd = diffuse_albedo(scene_, s);
    if (observer_) observer_->local(m.Ke + kd);
    return m.Ke + kd;
  }
  const Vec3f direct = direct_light(s, m, diffuse_albedo(scene_, s), -normalize(ray.dir), rays);
  const Bounce b = bounce(ray, s, direct, depth, weight);
  if (observer_) observer_->local(b.local);
  return finish(b, depth, rays);
}

Vec3f Whitted::finish(const Bounce& b, int depth, RayCounts& rays) const {
  Vec3f radiance = b.local;
  follow(RayKind::reflection, b.reflection, depth, radiance, rays);
  follow(RayKind::refraction, b.refraction, depth, radiance, rays);
  return radiance;
}

}  // namespace rayvec
