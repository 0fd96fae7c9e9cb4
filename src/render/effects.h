// The effects plan: which kinds of secondary rays a scene can need, derived from its lights and the
// MTL illumination models of the materials its triangles use. The integrator spawns a ray kind only
// where the material asks for it; the plan is what `rayvec render` prints at start.
#pragma once
#include <string>

#include "scene/scene.h"

namespace rayvec {

// MTL illum 3–7 trace reflections, provided Ks > 0.
bool reflects(const Material& m);
// MTL illum 6–7 trace refraction (Snell with Ni), provided Tf > 0.
bool refracts(const Material& m);
// MTL illum 5 and 7 weight reflection (and 7 refraction) by the Fresnel equations.
bool uses_fresnel(const Material& m);

struct EffectsPlan {
  int shadow_lights = 0;          // lights with non-zero power (each may cast shadow rays)
  int reflective_materials = 0;   // materials in use that reflect
  int refractive_materials = 0;   // materials in use that refract
  // "effects: shadows (2 lights), reflection (2 materials), refraction: none"
  std::string describe() const;
};

EffectsPlan plan_effects(const Scene& scene);

}  // namespace rayvec
