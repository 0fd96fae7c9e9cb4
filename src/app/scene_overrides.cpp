#include "app/scene_overrides.h"

#include <sstream>

#include "app/command_line.h"
#include "io/input_error.h"

namespace rayvec {

void add_scene_overrides(Command& cmd, SceneOverrides& o) {
  cmd.option("--spp", o.spp, "samples per pixel, stratified (0 = the scene's render.spp)")
      .option("--max-depth", o.max_depth, "reflection/refraction depth cap (-1 = scene's)")
      .option("--min-contribution", o.min_contribution,
              "skip secondary rays weighing less than this (-1 = scene's)")
      .option("--width", o.width, "image width in pixels (0 = the scene camera's)")
      .option("--height", o.height, "image height in pixels (0 = the scene camera's)")
      .option("--effects", o.effects,
              "secondary rays allowed, comma-separated from shadows,reflection,refraction, or all, none "
              "(default all); without shadows every light reaches every point facing it");
}

RenderSettings::Effects parse_effects(const std::string& list) {
  RenderSettings::Effects e{false, false, false};
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) {
    if (item == "shadows")
      e.shadows = true;
    else if (item == "reflection")
      e.reflection = true;
    else if (item == "refraction")
      e.refraction = true;
    else if (item == "all")
      e = {};
    else if (item != "none")
      throw InputError("--effects: unknown '" + item +
                       "' (choose from shadows, reflection, refraction, or all, none; e.g. "
                       "--effects shadows,reflection)");
  }
  return e;
}

void apply_scene_overrides(const SceneOverrides& a, Scene& scene) {
  RenderSettings& r = scene.render;
  if (a.spp < 0 || a.spp > 4096) throw InputError("--spp: must be between 1 and 4096");
  if (a.spp > 0) r.spp = a.spp;
  if (a.max_depth < -1 || a.max_depth > 64) throw InputError("--max-depth: must be between 0 and 64");
  if (a.max_depth >= 0) r.max_depth = a.max_depth;
  if (a.min_contribution != -1 && !(a.min_contribution >= 0 && a.min_contribution <= 1))
    throw InputError("--min-contribution: must be between 0 and 1");
  if (a.min_contribution >= 0) r.min_contribution = float(a.min_contribution);
  if (a.width < 0 || a.width > 16384 || a.height < 0 || a.height > 16384)
    throw InputError("--width/--height: must be between 1 and 16384");
  if (a.width > 0) scene.camera.width = a.width;
  if (a.height > 0) scene.camera.height = a.height;
  if (!a.effects.empty()) r.effects = parse_effects(a.effects);
}

}  // namespace rayvec
