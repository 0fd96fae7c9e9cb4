// `rayvec render SCENE.json|MODEL.obj -o image.png|.exr`: the Whitted renderer's front end.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/scene_overrides.h"
#include "app/trace_options.h"
#include "distributed/render_across_ranks.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "io/error_report.h"
#include "io/input_error.h"
#include "io/progress.h"
#include "platform/stopwatch.h"
#include "render/effects.h"
#include "render/heatmap.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

struct RenderArgs {
  std::string scene, output, aov, stats_json;
  SceneOverrides overrides;
  bool stats = false, quiet = false, heatmap = false;
  TraceOptions trace;
  bool strict = false;  // loading warnings are errors
};

RenderSettings::Aovs parse_aovs(const std::string& list, const std::string& output) {
  RenderSettings::Aovs aov;
  if (list.empty()) return aov;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) {
    if (item == "depth")
      aov.depth = true;
    else if (item == "normal")
      aov.normal = true;
    else if (item == "id")
      aov.id = true;
    else if (item == "cost")
      aov.cost = true;
    else if (item == "bounces")
      aov.bounces = true;
    else
      throw InputError("--aov: unknown '" + item + "' (choose from depth, normal, id, cost, bounces)");
  }
  if (output.size() < 4 || output.substr(output.size() - 4) != ".exr")
    throw InputError("--aov: extra channels need an .exr output (got " + output + ")");
  return aov;
}

// Pixels whose colour differs from the background.
std::size_t non_background_pixels(const Image& image, Vec3f background) {
  std::size_t n = 0;
  const std::size_t channels = image.channels.size();
  for (std::size_t i = 0; i + 2 < image.pixels.size(); i += channels)
    n += image.pixels[i] != background.x || image.pixels[i + 1] != background.y ||
         image.pixels[i + 2] != background.z;
  return n;
}

// Triangles whose corners are collinear (e1 × e2 = 0, in double from the float corners): no ray hits them.
std::size_t zero_area_triangles(const TriangleMesh& mesh) {
  std::size_t n = 0;
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const Vec3d v0(mesh.vertex(t, 0)), v1(mesh.vertex(t, 1)), v2(mesh.vertex(t, 2));
    n += cross(v1 - v0, v2 - v0) == Vec3d{0, 0, 0} ? 1 : 0;
  }
  return n;
}

// An image of nothing but the background says why, by the camera rays that hit: none (the camera
// looks past the geometry, or every triangle has zero area), or some (what they hit is unlit).
void warn_if_only_background(const std::string& name, const Image& image, const Scene& scene,
                             const RayCounts& rays) {
  if (non_background_pixels(image, scene.background) != 0) return;
  if (rays.primary_hits != 0) {
    std::fprintf(stderr,
                 "warning: %s: the image shows only the background colour: the camera sees geometry "
                 "(%llu of %llu camera rays hit it) but no light reaches what it sees (check the lights, "
                 "their intensity and the ambient colour)\n",
                 name.c_str(), (unsigned long long)rays.primary_hits, (unsigned long long)rays.primary);
  } else if (zero_area_triangles(scene.mesh) == scene.mesh.size()) {
    std::fprintf(stderr,
                 "warning: %s: the image shows only the background: the mesh's triangles (%zu) all have zero "
                 "area (collinear corners), and no ray hits such a triangle\n",
                 name.c_str(), scene.mesh.size());
  } else {
    std::fprintf(stderr,
                 "warning: %s: the image shows only the background: the camera sees no geometry "
                 "(try the default view, --view iso, or check --eye/--look-at)\n",
                 name.c_str());
  }
}

// --heatmap: each cost/bounces channel as a false-colour PNG beside the EXR, with a legend.
void write_heatmaps(const RenderArgs& a, const Image& image, bool quiet) {
  const std::string stem = a.output.substr(0, a.output.size() - 4);
  for (int c = 3; c < image.nchannels(); ++c) {
    const std::string& name = image.channels[c];
    if (name != "cost.nodes" && name != "cost.triangles" && name != "bounces") continue;
    const std::string path = stem + "." + name.substr(name.find('.') + 1) + ".png";
    const Heatmap h = make_heatmap(image, c, /*log_scale=*/name != "bounces");
    write_image(path, h.image, {{"rayvec:scene", a.scene}, {"rayvec:channel", name}});
    if (!quiet)
      std::printf("wrote %s (%s from %s to %s)\n", path.c_str(), name.c_str(), legend_number(h.lo).c_str(),
                  legend_number(h.hi).c_str());
  }
}

int run_render(RenderArgs& a) {
  check_threads_option(a.trace.threads);  // before the scene is loaded, not after
  if (!is_writable_image_path(a.output))
    throw InputError("-o: unknown image extension in '" + a.output + "' (use .png or .exr)");
  // Fail before the work, not after it: an unwritable -o is found by opening (and dropping) the
  // temporary the image will later be written through (AtomicFile::check). Rank 0 writes.
  if (cluster().root()) {
    AtomicFile::check(a.output);
    require_image_writer(a.output);
  }
  if (!a.stats_json.empty()) {
    std::error_code e1, e2;
    if (std::filesystem::weakly_canonical(a.stats_json, e1) ==
            std::filesystem::weakly_canonical(a.output, e2) &&
        !e1 && !e2)
      throw InputError("--stats-json: " + a.stats_json + " is the image -o writes (give another file name)");
    if (cluster().root()) AtomicFile::check(a.stats_json);
  }
  const RenderSettings::Aovs aov = parse_aovs(a.aov, a.output);
  if (a.heatmap && !aov.cost && !aov.bounces)
    throw InputError("--heatmap: draws the cost and bounces AOVs; add --aov cost,bounces (or one of them)");
  RenderStats stats;

  auto t = std::chrono::steady_clock::now();
  Scene scene = load_scene(a.scene, requested_threads(a.trace));
  apply_scene_overrides(a.overrides, scene);
  scene.render.aov = aov;
  const RenderSettings& settings = scene.render;
  if (a.trace.intersector.empty()) a.trace.intersector = render_intersector(scene);
  const TraceConfig config = resolve_trace_options(a.trace);
  const AccelKind kind = resolve_accel(a.trace);
  stats.load_seconds = seconds_since(t);
  report_warnings(scene.warnings, a.strict ? "error" : "warning");
  if (a.strict && !scene.warnings.empty())
    throw InputError(a.scene + ": " + std::to_string(scene.warnings.size()) +
                     " problem(s) while loading, and --strict makes them errors");

  t = std::chrono::steady_clock::now();
  const auto accel = make_accelerator(kind, scene.mesh, config);
  stats.build_seconds = seconds_since(t);

  char settings_text[256];
  std::snprintf(settings_text, sizeof settings_text,
                "%dx%d spp=%d max_depth=%d min_contribution=%g accel=%s isa=%s intersector=%s",
                scene.camera.width, scene.camera.height, settings.spp, settings.max_depth,
                double(settings.min_contribution), accel_name(kind), isa_name(config.isa),
                intersector_name(config.intersector));
  const RenderSettings::Effects& fx = settings.effects;
  if (!fx.shadows || !fx.reflection || !fx.refraction) {
    std::string on = std::string(fx.shadows ? ",shadows" : "") + (fx.reflection ? ",reflection" : "") +
                     (fx.refraction ? ",refraction" : "");
    on = on.empty() ? "none" : on.substr(1);
    std::strncat(settings_text, (" effects=" + on).c_str(),
                 sizeof settings_text - std::strlen(settings_text) - 1);
  }
  if (!a.quiet) {
    std::printf("%s\n", plan_effects(scene).describe().c_str());
    std::printf("scene: %s, %zu triangles, %zu lights; %s\n", a.scene.c_str(), scene.mesh.size(),
                scene.lights.size(), settings_text);
    std::fflush(stdout);
  }

  ProgressBar bar(!a.quiet);
  RankLoads loads;
  const Image image = render_across_ranks(cluster(), scene, *accel, settings, stats, loads, bar.progress());
  bar.finish();                     // render() has drawn it at 100 %
  if (!cluster().root()) return 0;  // rank 0 has the image
  warn_if_only_background(a.scene, image, scene, stats.rays);

  t = std::chrono::steady_clock::now();
  write_image(a.output, image,
              {{"rayvec:scene", a.scene},
               {"rayvec:settings", settings_text},
               {"rayvec:render_seconds", std::to_string(stats.render_seconds)}});
  stats.write_seconds = seconds_since(t);
  if (!a.quiet) std::printf("wrote %s (%.3f s)\n", a.output.c_str(), stats.render_seconds);
  if (a.stats) std::printf("intersector: %s\n%s", intersector_name(config.intersector), stats.text().c_str());
  if (a.stats && cluster().distributed()) std::printf("%s", loads.text().c_str());
  if (a.heatmap) write_heatmaps(a, image, a.quiet);
  if (!a.stats_json.empty()) {
    AtomicFile file(a.stats_json);
    const std::string json = stats.json();
    std::fputs(json.c_str(), file.stream());
    file.commit();
  }
  return 0;
}

}  // namespace

void register_render_command(CommandLine& cli) {
  static RenderArgs a;
  a.trace.intersector = "";  // "" = the scene's render.intersector, else watertight
  Command& cmd =
      cli.command("render", "Render a JSON scene or a bare OBJ with Whitted ray tracing")
          .positional("SCENE", a.scene, "scene.json, or model.obj (camera frames it, light at eye)")
          .required("-o,--output", a.output, "image.png (8-bit sRGB) or image.exr (linear float)")
          .option("--aov", a.aov,
                  "extra EXR channels, comma-separated: depth,normal,id (first sample), cost (BVH nodes "
                  "visited and triangles tested by all rays of the pixel), bounces (deepest ray)")
          .flag("--heatmap", a.heatmap,
                "with --aov cost/bounces: also OUTPUT.nodes.png, .triangles.png, .bounces.png, false "
                "colour with a legend")
          .flag("--stats", a.stats, "print ray counts per kind, rays/s and time per stage")
          .option("--stats-json", a.stats_json, "write the statistics as JSON to this file")
          .flag("-q,--quiet", a.quiet, "print nothing but errors (and --stats)")
          .flag("--strict", a.strict,
                "treat every loading warning (missing texture, MTL value clamped, ...) as an error");
  add_scene_overrides(cmd, a.overrides);
  add_trace_options(cmd, a.trace, /*with_accel=*/true);
  cmd.footer(
         "--intersector defaults to the scene's render.intersector, else watertight.\n"
         "A bare OBJ (or a scene without \"camera\") is framed from the iso view so that its\n"
         "bounding box fills the image, lit by a point light at the eye.\n"
         "Examples:\n"
         "  rayvec render scenes/whitted.json -o whitted.png\n"
         "  rayvec render model.obj -o top.png --view top\n"
         "  rayvec render model.obj -o close.png --eye 0,2,5 --look-at 0,1,0 --fov 30\n"
         "  rayvec render model.obj -o model.exr --aov depth,normal,id --spp 4 --stats\n"
         "  rayvec render scenes/whitted.json -o w.exr --aov cost,bounces --heatmap   # where the BVH works\n"
         "  rayvec render scenes/whitted.json -o w.png --max-depth 1 --effects shadows,reflection\n"
         "The cost AOV counts the work of the scalar single-ray traversal (the same tree), tracing every\n"
         "ray once more to count it; follow one pixel's rays with `rayvec trace`.")
      .run([] { return run_render(a); });
}

}  // namespace rayvec
