// The effects plan: which kinds of secondary rays a scene can need, derived from its lights and the
// shading models of the materials its triangles use (shaders/shading_model.h says which models
// spawn which rays). The integrator spawns a ray kind only where the material asks for it; the plan
// is what `rayvec render` prints at start.
#pragma once
#include <string>

#include "scene/scene.h"

namespace rayvec {

struct EffectsPlan {
  int shadow_lights = 0;            // lights with non-zero power (each may cast shadow rays)
  int reflective_materials = 0;     // materials in use that reflect
  int refractive_materials = 0;     // materials in use that refract
  RenderSettings::Effects enabled;  // scene.render.effects: a kind switched off is described as off
  // "effects: shadows (2 lights), reflection (2 materials), refraction: none" ("…: off" for a kind
  // switched off by --effects)
  std::string describe() const;
};

EffectsPlan plan_effects(const Scene& scene);

}  // namespace rayvec
