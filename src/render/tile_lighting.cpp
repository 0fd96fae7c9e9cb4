#include "render/tile_lighting.h"

#include "render/light_sample.h"
#include "render/offset_ray.h"
#include "shaders/blinn_phong.h"
#include "shaders/lambert.h"
#include "shaders/shading_model.h"

namespace rayvec {
namespace {

// c ? a : b by components: no branch in a loop over lanes.
inline Vec3f select(bool c, Vec3f a, Vec3f b) { return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z}; }

// The direction to the eye (from the ray's direction, in place) and the shadow rays' origin.
void eye_and_origin_lanes(Lanes3In p, Lanes3In ng, Lanes3Out to_eye, Lanes3Out origin, int n) {
  for (int j = 0; j < n; ++j) {
    to_eye.set(j, -normalize(Vec3f{to_eye.x[j], to_eye.y[j], to_eye.z[j]}));
    origin.set(j, offset_ray_origin(p[j], ng[j]));
  }
}

// One light's samples of n hits: irradiance, Blinn–Phong's cos θh, and whether it faces a lit hit.
template <Light::Type type>
void sample_lanes(const Light& light, Lanes3In p, Lanes3In ng, Lanes3In ns, Lanes3In to_eye,
                  const int32_t* __restrict lit, Lanes3Out irradiance, float* __restrict cos_h,
                  int32_t* __restrict reaches, int n) {
  const Vec3f position = light.position, direction = light.direction, power = light.power;
  for (int j = 0; j < n; ++j) {
    const LightSample l = type == Light::Type::point
                              ? point_light_sample(position, power, p[j], ng[j], ns[j])
                              : directional_light_sample(direction, power, ng[j], ns[j]);
    irradiance.set(j, l.irradiance);
    cos_h[j] = shaders::blinn_phong_cos(ns[j], l.to_light, to_eye[j]);
    reaches[j] = lit[j] & int32_t(l.faces);
  }
}

// Whitted::direct_light's sum over n hits, for one light: Lambert, plus shaders::blinn_phong where
// the model has a highlight (0 where Ks is 0 or cos θh is not positive), added where it reaches.
void add_lanes(Lanes3In kd, Lanes3In ks, const int32_t* __restrict highlight,
               const int32_t* __restrict specular, Lanes3In irradiance, const float* __restrict cos_h,
               const float* __restrict lobe, const int32_t* __restrict reaches, Lanes3Out sum, int n) {
  for (int j = 0; j < n; ++j) {
    const Vec3f e = irradiance[j];
    const Vec3f diffuse = shaders::lambert(kd[j], e);
    const Vec3f spec = select((specular[j] != 0) & (cos_h[j] > 0), ks[j] * e * lobe[j], Vec3f{});
    const Vec3f lit = select(highlight[j] != 0, diffuse + spec, diffuse);
    const Vec3f before{sum.x[j], sum.y[j], sum.z[j]};
    sum.set(j, select(reaches[j] != 0, before + lit, before));
  }
}

// shade()'s local term of a lit hit whose material spawns no ray, over n hits: Ka·ambient + direct
// light + Ke, as Whitted::shade_hit sums it.
void local_lanes(Lanes3In ka, Vec3f ambient, Lanes3In direct, Lanes3In ke, Lanes3Out radiance, int n) {
  for (int j = 0; j < n; ++j) radiance.set(j, ka[j] * ambient + direct[j] + ke[j]);
}

}  // namespace

TileLighting::TileLighting(const Scene& scene, const Accelerator& accel, const Whitted& whitted)
    : scene_(scene), accel_(accel), whitted_(whitted) {
  for (const Material& m : scene.materials) local_only_.push_back(Whitted::local_only(m));
}

void TileLighting::light(const Ray* rays, const Hit* hits, int n) {
  load_hits(rays, hits, n);
  for (const Light& light : scene_.lights) {
    if (!has_power(light)) continue;
    sample(light, n);
    if (whitted_.shadows_on()) trace_shadows(light, n);
    add_reaching(n);
  }
  local_lanes(in(ka_), scene_.ambient, in(sum_), in(ke_), out(radiance_), n);
}

void TileLighting::load_hits(const Ray* rays, const Hit* hits, int n) {
  surfaces_.resize(std::size_t(n));
  for (auto* v : {&lit_, &finished_, &highlight_, &specular_, &reaches_}) v->resize(std::size_t(n));
  for (auto* v :
       {&p_, &ng_, &ns_, &origin_, &to_eye_, &kd_, &ks_, &ka_, &ke_, &sum_, &radiance_, &irradiance_})
    v->resize(n);
  ns_exp_.resize(std::size_t(n));
  cos_h_.resize(std::size_t(n));
  lobe_.resize(std::size_t(n));
  shadow_rays_ = 0;
  for (int j = 0; j < n; ++j) {
    SurfacePoint& s = surfaces_[j];
    lit_[j] = whitted_.lit_surface(rays[j], hits[j], s);
    sum_.set(j, Vec3f{});
    if (!lit_[j]) {  // lanes that are computed and never read
      for (auto* v : {&p_, &ng_, &ns_, &to_eye_, &kd_, &ks_, &ka_, &ke_}) v->set(j, Vec3f{});
      finished_[j] = highlight_[j] = specular_[j] = 0;
      ns_exp_[j] = 0;
      continue;
    }
    const Material& m = scene_.materials[s.material];
    p_.set(j, s.p);
    ng_.set(j, s.ng);
    ns_.set(j, s.ns);
    to_eye_.set(j, rays[j].dir);  // normalized below
    kd_.set(j, diffuse_albedo(scene_, s));
    ks_.set(j, m.Ks);
    ka_.set(j, m.Ka);
    ke_.set(j, m.Ke);
    finished_[j] = local_only_[std::size_t(s.material)];
    ns_exp_[j] = m.Ns;
    highlight_[j] = shaders::has_highlight(shaders::shading_model(m));
    specular_[j] = shaders::has_specular(m.Ks);
  }
  eye_and_origin_lanes(in(p_), in(ng_), out(to_eye_), out(origin_), n);
}

void TileLighting::sample(const Light& light, int n) {
  // one loop per light type: a loop without branches runs in SIMD lanes
  const auto lanes = light.type == Light::Type::point ? sample_lanes<Light::Type::point>
                                                      : sample_lanes<Light::Type::directional>;
  lanes(light, in(p_), in(ng_), in(ns_), in(to_eye_), lit_.data(), out(irradiance_), cos_h_.data(),
        reaches_.data(), n);
}

void TileLighting::trace_shadows(const Light& light, int n) {
  shadow_batch_.resize(std::size_t(n));
  shadow_hit_.resize(std::size_t(n));
  std::size_t count = 0;
  for (int j = 0; j < n; ++j) {
    if (!reaches_[j]) continue;
    shadow_batch_[count] = shadow_ray(light, origin_[j]);
    shadow_hit_[count++] = j;
  }
  shadow_rays_ += count;
  blocked_.resize(count);
  accel_.occluded_stream(shadow_batch_.data(), blocked_.data(), count);
  for (std::size_t k = 0; k < count; ++k)
    if (blocked_[k]) reaches_[shadow_hit_[k]] = 0;
}

void TileLighting::add_reaching(int n) {
  // The power, one hit at a time: std::pow has no lane form that gives its bits.
  for (int j = 0; j < n; ++j)
    lobe_[j] = (reaches_[j] & highlight_[j] & specular_[j]) != 0 && cos_h_[j] > 0
                   ? shaders::blinn_phong_lobe(ns_exp_[j], cos_h_[j])
                   : 0.0f;
  add_lanes(in(kd_), in(ks_), highlight_.data(), specular_.data(), in(irradiance_), cos_h_.data(),
            lobe_.data(), reaches_.data(), out(sum_), n);
}

}  // namespace rayvec
