#include "render/effects.h"

#include <vector>

#include "shaders/shading_model.h"

namespace rayvec {
namespace {

std::string count(int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

EffectsPlan plan_effects(const Scene& scene) {
  EffectsPlan plan;
  plan.enabled = scene.render.effects;
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
  auto item = [](bool on, int n, const char* what) {
    return !on ? std::string(": off") : n ? " (" + count(n, what) + ")" : std::string(": none");
  };
  return "effects: shadows" + item(enabled.shadows, shadow_lights, "light") + ", reflection" +
         item(enabled.reflection, reflective_materials, "material") + ", refraction" +
         item(enabled.refraction, refractive_materials, "material");
}

}  // namespace rayvec
