// `rayvec trace SCENE --pixel X,Y [--sample K] [--json]`: the ray tree of one pixel — every ray the
// renderer traced for it, recorded through the integrator's observer hook while the pixel is
// rendered exactly as `rayvec render` renders it (same scene overrides, same sampling).
#include <cstdio>
#include <string>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/scene_overrides.h"
#include "app/trace_options.h"
#include "io/error_report.h"
#include "io/input_error.h"
#include "render/ray_tree.h"
#include "render/ray_tree_format.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

struct TraceArgs {
  std::string scene, pixel;
  int sample = 0;
  bool json = false;
  SceneOverrides overrides;
  TraceOptions trace;
};

// "X,Y": two non-negative decimal integers inside the image.
std::pair<int, int> parse_pixel(const std::string& text, const Camera& cam) {
  const std::string how = " (expected X,Y with 0 <= X < " + std::to_string(cam.width) + " and 0 <= Y < " +
                          std::to_string(cam.height) + ", e.g. --pixel 10,20)";
  const std::size_t comma = text.find(',');
  auto integer = [&](const std::string& s) {
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
      throw InputError("--pixel: '" + text + "' is not a pixel" + how);
    return std::stoi(s);
  };
  if (comma == std::string::npos) throw InputError("--pixel: '" + text + "' is not a pixel" + how);
  const int x = integer(text.substr(0, comma)), y = integer(text.substr(comma + 1));
  if (x >= cam.width || y >= cam.height)
    throw InputError("--pixel: " + text + " lies outside the " + std::to_string(cam.width) + "x" +
                     std::to_string(cam.height) + " image" + how);
  return {x, y};
}

int run_trace(TraceArgs& a) {
  Scene scene = load_scene(a.scene, requested_threads(a.trace));
  apply_scene_overrides(a.overrides, scene);
  const auto [x, y] = parse_pixel(a.pixel, scene.camera);
  const int spp = std::max(1, scene.render.spp);
  if (a.sample < 0 || a.sample >= spp)
    throw InputError("--sample: " + std::to_string(a.sample) + " is not a sample of this pixel (0 to " +
                     std::to_string(spp - 1) + " with spp " + std::to_string(spp) + ")");
  if (a.trace.intersector.empty()) a.trace.intersector = render_intersector(scene);
  const TraceConfig config = resolve_trace_options(a.trace);
  report_warnings(scene.warnings);
  const auto accel = make_accelerator(resolve_accel(a.trace), scene.mesh, config);
  const PixelTrace tree = trace_pixel(scene, *accel, scene.render, x, y, a.sample);
  const std::string out = a.json ? ray_tree_json(tree, scene) : ray_tree_text(tree, scene);
  std::fputs(out.c_str(), stdout);
  return 0;
}

}  // namespace

void register_trace_command(CommandLine& cli) {
  static TraceArgs a;
  a.trace.intersector = "";  // as render: the scene's render.intersector, else the default
  Command& cmd =
      cli.command("trace", "Print the ray tree of one pixel: every ray the renderer traced for it")
          .positional("SCENE", a.scene, "scene.json, or model.obj (as for render)")
          .required("--pixel", a.pixel, "the pixel X,Y (0,0 = top left)")
          .option("--sample", a.sample, "which of the pixel's spp samples to follow (default 0)")
          .flag("--json", a.json, "machine-readable JSON (schema in docs/formats.md) instead of text");
  add_scene_overrides(cmd, a.overrides);
  add_trace_options(cmd, a.trace, /*with_accel=*/true);
  cmd.footer(
         "Each ray: its kind (camera, shadow, reflection, refraction), origin, direction, the triangle it\n"
         "hits (id, object, material) and t, its weight (the depth control's), what it adds to the pixel,\n"
         "the BVH work it cost, and why it stops: miss, light_blocked, light_reached, diffuse, unlit,\n"
         "max_depth, contribution_cutoff, total_internal_reflection, effect_off. Give the same scene\n"
         "options as to `render` and the tree is exactly what made that pixel of the image.\n"
         "Examples:\n"
         "  rayvec trace scenes/whitted.json --pixel 330,250 --width 640 --height 480\n"
         "  rayvec trace scenes/whitted.json --pixel 330,250 --sample 3 --json > ray.json")
      .run([] { return run_trace(a); });
}

}  // namespace rayvec
