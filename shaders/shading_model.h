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

ShadingModel shading_model(int illum);
inline ShadingModel shading_model(const Material& m) { return shading_model(m.illum); }

// "constant", "diffuse", ..., as in the enum.
const char* shading_model_name(ShadingModel model);

// The model responds to lights (ambient, direct light and shadow rays); false for constant only.
bool is_lit(ShadingModel model);
// The model adds the Blinn–Phong highlight to the direct light.
bool has_highlight(ShadingModel model);
// The model traces a mirror ray (before asking the material for a non-zero Ks).
bool reflects(ShadingModel model);
// The model traces a refraction ray (before asking the material for a non-zero Tf).
bool refracts(ShadingModel model);
// The model weights its mirror ray, and its refraction ray if any, by the Fresnel equations.
bool uses_fresnel(ShadingModel model);

// A material spawns mirror rays when its model reflects and Ks > 0, refraction rays when its model
// refracts and Tf > 0: the rays the effects plan counts and the integrator traces.
bool reflects(const Material& m);
bool refracts(const Material& m);
inline bool uses_fresnel(const Material& m) { return uses_fresnel(shading_model(m)); }

// The weights of the two secondary rays of a material that spawns them, given the Fresnel
// reflectance `fresnel` at the hit (pass 1 for models without Fresnel): Ks·F for the mirror ray;
// Tf·(1 − F) for the refraction ray of fresnel_glass, Tf for glass.
Vec3f reflection_weight(const Material& m, float fresnel);
Vec3f transmission_weight(const Material& m, float fresnel);

}  // namespace rayvec::shaders
