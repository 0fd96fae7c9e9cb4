#include "render/effects.h"

#include <vector>

#include "shaders/shading_model.h"

namespace rayvec {
namespace {

std::string count(int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

EffectsPlan plan_effects(const Scene& scene) {
  EffectsPlan plan;
  for (const Light& l : scene.lights)
    if (max_component(l.power) > 0) ++plan.shadow_lights;
  std::vector<char> used(scene.materials.size(), 0);
  for (int32_t m : scene.triangle_material) used[m] = 1;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (!used[i]) continue;
    plan.reflective_materials += shaders::reflects(scene.materials[i]);
    plan.refractive_materials += shaders::refracts(scene.materials[i]);
  }
  return plan;
}

std::string EffectsPlan::describe() const {
  std::string s = "effects: shadows";
  s += shadow_lights ? " (" + count(shadow_lights, "light") + ")" : ": none";
  s += ", reflection";
  s += reflective_materials ? " (" + count(reflective_materials, "material") + ")" : ": none";
  s += ", refraction";
  s += refractive_materials ? " (" + count(refractive_materials, "material") + ")" : ": none";
  return s;
}

}  // namespace rayvec
