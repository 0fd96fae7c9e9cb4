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

Vec3f Whitted::trace(const Ray& ray, int depth, float weight, RayCounts& rays) const {
  return shade(ray, accel_.closest(ray), depth, weight, rays);
}

Vec3f Whitted::direct_light(const SurfacePoint& s, const Material& m, Vec3f kd, Vec3f to_eye,
                            RayCounts& rays) const {
  Vec3f sum{};
  const bool highlight = shaders::has_highlight(shaders::shading_model(m));
  const Vec3f origin = offset_ray_origin(s.p, s.ng);
  for (const Light& light : scene_.lights) {
    if (max_component(light.power) <= 0) continue;
    Vec3f to_light, irradiance;
    Ray shadow{origin, {}, 0.0f, kInf};
    if (light.type == Light::Type::point) {
      const Vec3f d = light.position - s.p;
      const float r2 = dot(d, d);
      if (!(r2 > 0)) continue;
      to_light = d * (1.0f / std::sqrt(r2));
      irradiance = light.power * (1.0f / r2);  // I / r²
      shadow.dir = light.position - origin;    // the light sits at t = 1
      shadow.tmax = kBeforeLight;
    } else {
      to_light = -light.direction;
      irradiance = light.power;
      shadow.dir = to_light;
    }
    // Only lights on the lit side of both normals can contribute: no shadow ray otherwise.
    const float cos_s = dot(s.ns, to_light);
    if (!(dot(s.ng, to_light) > 0) || !(cos_s > 0)) continue;
    ++rays.shadow;
    if (accel_.occluded(shadow)) continue;
    const Vec3f e = irradiance * cos_s;
    sum += shaders::lambert(kd, e);
    if (highlight) sum += shaders::blinn_phong(m.Ks, m.Ns, s.ns, to_light, to_eye, e);
  }
  return sum;
}

Vec3f Whitted::shade(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays) const {
  if (!hit.hit()) return scene_.background;
  const SurfacePoint s = surface_point(scene_, ray, hit);
  const Material& m = scene_.materials[s.material];
  const shaders::ShadingModel model = shaders::shading_model(m);
  const Vec3f kd = diffuse_albedo(scene_, s);
  if (!shaders::is_lit(model)) return m.Ke + kd;  // constant colour, no lighting

  const Vec3f dir = normalize(ray.dir);
  Vec3f radiance = m.Ka * scene_.ambient + direct_light(s, m, kd, -dir, rays);
  if (shaders::refracts(m)) radiance *= m.d;  // dissolve: the local term's opacity over the refraction
  radiance += m.Ke;

  // Fresnel reflectance for the Fresnel models: n1 on the incoming side, n2 beyond.
  const float n1 = s.entering ? 1.0f : m.Ni, n2 = s.entering ? m.Ni : 1.0f;
  const float fresnel =
      shaders::uses_fresnel(model) ? shaders::fresnel_dielectric(-dot(dir, s.ns), n1, n2) : 1.0f;

  if (shaders::reflects(m)) {
    const Vec3f kr = shaders::reflection_weight(m, fresnel);
    const float w = weight * max_component(kr);
    if (child_worthwhile(depth, w)) {
      Vec3f r = shaders::mirror_direction(dir, s.ns);
      if (!(dot(r, s.ng) > 0)) r = shaders::mirror_direction(dir, s.ng);  // shading normal too bent
      ++rays.reflection;
      radiance += kr * trace(Ray{offset_ray_origin(s.p, s.ng), r, 0.0f, kInf}, depth + 1, w, rays);
    }
  }
  if (shaders::refracts(m)) {
    const Vec3f kt = shaders::transmission_weight(m, fresnel);
    const float w = weight * max_component(kt);
    if (child_worthwhile(depth, w)) {
      std::optional<Vec3f> t = shaders::refract_direction(dir, s.ns, n1 / n2);
      if (t && !(dot(*t, s.ng) < 0)) t = shaders::refract_direction(dir, s.ng, n1 / n2);
      if (t) {  // none under total internal reflection: the Fresnel reflection carries it all
        ++rays.refraction;
        radiance += kt * trace(Ray{offset_ray_origin(s.p, -s.ng), *t, 0.0f, kInf}, depth + 1, w, rays);
      }
    }
  }
  return radiance;
}

}  // namespace rayvec
