// The command-line overrides of a scene's render settings and camera size that `render` and
// `trace` share, so that `trace` follows a pixel under exactly the settings `render` used.
#pragma once
#include <string>

#include "scene/scene.h"

namespace rayvec {

class Command;

struct SceneOverrides {
  int spp = 0, max_depth = -1, width = 0, height = 0;  // 0 / -1: not given
  double min_contribution = -1;
  std::string effects;  // "" = all on
};

// Declares --spp, --max-depth, --min-contribution, --width, --height and --effects on `cmd`.
void add_scene_overrides(Command& cmd, SceneOverrides& o);

// Command-line values win over the scene's "render" block and camera. InputError (exit 2) for a
// value out of range or an unknown effect.
void apply_scene_overrides(const SceneOverrides& o, Scene& scene);

// "shadows,reflection" → the effects switched on; "all" and "none" too.
RenderSettings::Effects parse_effects(const std::string& list);

}  // namespace rayvec
