// The material model: which shading model an MTL material asks for, and what each model asks of the
// integrator (lighting, highlight, mirror rays, refraction rays, Fresnel weights). The MTL
// illumination numbers (Wavefront MTL, `illum`) are read here and nowhere else; the integrator asks
// shading_model() and the predicates below, and the BRDFs and directions live one per file
// (lambert.h, blinn_phong.h, mirror.h, dielectric.h, fresnel.h).
#pragma once
#include "math/vec3.h"
#include "scene/material.h"

namespace rayvec::shaders {

// The shading models rayvec implements, and the MTL illum values that select them:
//   constant        illum 0      Kd + Ke: no lighting, no rays
//   diffuse         illum 1      Ka·ambient + Lambert (Kd/π) under the lights + Ke
//   blinn_phong     illum 2      diffuse + the Blinn–Phong highlight (Ks, Ns)
//   mirror          illum 3, 4   blinn_phong + a mirror ray weighted by Ks
//   fresnel_mirror  illum 5      blinn_phong + a mirror ray weighted by Ks·F (F: Fresnel reflectance)
//   glass           illum 6      blinn_phong with its lit part (not Ke) times the dissolve d, + a
//                                mirror ray (Ks) and a refraction ray (Tf; Snell with Ni)
//   fresnel_glass   illum 7      as glass, the mirror ray weighted by Ks·F, the refraction ray by
//                                Tf·(1 − F)
// A material spawns a ray only where its weight (Ks, Tf) is non-zero; a glass without a refraction
// ray (Tf = 0) is not dissolved. illum 4 (MTL: glass without refraction) is traced as a
// mirror. illum 8 and 9 (MTL: reflection map, no ray tracing) and 10 (shadow matte) are drawn with
// the Blinn–Phong model, as are values above 10; values below 0 are drawn as diffuse. Only an MTL
// file can give a value outside 0..10: scene JSON rejects it.
enum class ShadingModel { constant, diffuse, blinn_phong, mirror, fresnel_mirror, glass, fresnel_glass };

// Inline: the integrator asks these at every hit.
inline ShadingModel shading_model(int illum) {
  switch (illum) {
    case 0: return ShadingModel::constant;
    case 1: return ShadingModel::diffuse;
    case 3:
    case 4: return ShadingModel::mirror;
    case 5: return ShadingModel::fresnel_mirror;
    case 6: return ShadingModel::glass;
    case 7: return ShadingModel::fresnel_glass;
    default: return illum < 0 ? ShadingModel::diffuse : ShadingModel::blinn_phong;  // 2, 8, 9, 10, > 10
  }
}
inline ShadingModel shading_model(const Material& m) { return shading_model(m.illum); }

// "constant", "diffuse", ..., as in the enum.
const char* shading_model_name(ShadingModel model);

// The model responds to lights (ambient, direct light and shadow rays); false for constant only.
inline bool is_lit(ShadingModel model) { return model != ShadingModel::constant; }
// The model adds the Blinn–Phong highlight to the direct light.
inline bool has_highlight(ShadingModel model) {
  return model != ShadingModel::constant && model != ShadingModel::diffuse;
}
// The model traces a refraction ray (before asking the material for a non-zero Tf).
inline bool refracts(ShadingModel model) {
  return model == ShadingModel::glass || model == ShadingModel::fresnel_glass;
}
// The model traces a mirror ray (before asking the material for a non-zero Ks).
inline bool reflects(ShadingModel model) {
  return model == ShadingModel::mirror || model == ShadingModel::fresnel_mirror || refracts(model);
}
// The model weights its mirror ray, and its refraction ray if any, by the Fresnel equations.
inline bool uses_fresnel(ShadingModel model) {
  return model == ShadingModel::fresnel_mirror || model == ShadingModel::fresnel_glass;
}

// A material spawns mirror rays when its model reflects and Ks > 0, refraction rays when its model
// refracts and Tf > 0: the rays the effects plan counts and the integrator traces.
inline bool reflects(const Material& m) { return reflects(shading_model(m)) && max_component(m.Ks) > 0; }
inline bool refracts(const Material& m) { return refracts(shading_model(m)) && max_component(m.Tf) > 0; }
inline bool uses_fresnel(const Material& m) { return uses_fresnel(shading_model(m)); }

// The weights of the two secondary rays of a material that spawns them, given the Fresnel
// reflectance `fresnel` at the hit (pass 1 for models without Fresnel): Ks·F for the mirror ray;
// Tf·(1 − F) for the refraction ray of fresnel_glass, Tf for glass.
inline Vec3f reflection_weight(const Material& m, float fresnel) { return m.Ks * fresnel; }
inline Vec3f transmission_weight(const Material& m, float fresnel) {
  return m.Tf * (uses_fresnel(m) ? 1.0f - fresnel : 1.0f);
}

}  // namespace rayvec::shaders
