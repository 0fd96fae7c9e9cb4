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
  // The view of a scene without a camera, or one chosen on the command line.
  std::string view, eye, look_at, up;
  double fov = 0;
};

// Declares --spp, --max-depth, --min-contribution, --width, --height, --effects and the view
// options --view, --eye, --look-at, --up, --fov on `cmd`.
void add_scene_overrides(Command& cmd, SceneOverrides& o);

// Command-line values win over the scene's "render" block and camera; a scene without a camera or
// lights (a bare OBJ) is framed and lit as scene/default_view.h says, after the image size is
// known. InputError (exit 2) for a value out of range or an unknown effect or view.
void apply_scene_overrides(const SceneOverrides& o, Scene& scene);

// The intersector a render of `scene` uses when --intersector is not given: the scene's
// render.intersector, else watertight (mt lets rays slip between the triangles of closed meshes;
// benchmarks.md#decision-render-watertight gives the cost).
std::string render_intersector(const Scene& scene);

// "shadows,reflection" → the effects switched on; "all" and "none" too.
RenderSettings::Effects parse_effects(const std::string& list);

}  // namespace rayvec
