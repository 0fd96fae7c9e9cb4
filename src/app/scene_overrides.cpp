#include "app/scene_overrides.h"

#include <cmath>
#include <sstream>

#include "app/command_line.h"
#include "io/input_error.h"
#include "scene/default_view.h"

namespace rayvec {
namespace {

// "X,Y,Z" of --eye, --look-at, --up.
Vec3f parse_point(const std::string& text, const char* option) {
  Vec3f p;
  std::stringstream ss(text);
  std::string item;
  for (int k = 0; k < 3; ++k) {
    std::size_t used = 0;
    double v = 0;
    bool ok = static_cast<bool>(std::getline(ss, item, ','));
    try {
      v = ok ? std::stod(item, &used) : 0;
    } catch (const std::exception&) {
      ok = false;
    }
    if (!ok || used != item.size() || !std::isfinite(v) || std::fabs(v) > 1e30)
      throw InputError(std::string(option) + ": expected three numbers X,Y,Z (e.g. 0,1.5,4), got '" + text +
                       "'");
    p[k] = static_cast<float>(v);
  }
  if (std::getline(ss, item))
    throw InputError(std::string(option) + ": expected three numbers X,Y,Z, got '" + text + "'");
  return p;
}

CameraOverrides camera_overrides(const SceneOverrides& a) {
  CameraOverrides o;
  if (!a.view.empty()) o.view = parse_view(a.view);
  if (!a.eye.empty()) o.eye = parse_point(a.eye, "--eye");
  if (!a.look_at.empty()) o.look_at = parse_point(a.look_at, "--look-at");
  if (!a.up.empty()) o.up = parse_point(a.up, "--up");
  if (a.fov != 0) o.fov_y = static_cast<float>(a.fov);
  return o;
}

}  // namespace

void add_scene_overrides(Command& cmd, SceneOverrides& o) {
  cmd.option("--spp", o.spp, "samples per pixel, stratified (0 = the scene's render.spp)")
      .option("--max-depth", o.max_depth, "reflection/refraction depth cap (-1 = scene's)")
      .option("--min-contribution", o.min_contribution,
              "skip secondary rays weighing less than this (-1 = scene's)")
      .option("--width", o.width, "image width in pixels (0 = the scene camera's)")
      .option("--height", o.height, "image height in pixels (0 = the scene camera's)")
      .option("--effects", o.effects,
              "secondary rays allowed, comma-separated from shadows,reflection,refraction, or all, none "
              "(default all); without shadows every light reaches every point facing it")
      .option("--view", o.view,
              "frame the model from iso (front-right-above, the default without a scene camera), "
              "front, back, left, right, top or bottom")
      .option("--eye", o.eye, "camera position X,Y,Z (replaces the scene's or the view's)")
      .option("--look-at", o.look_at, "point looked at X,Y,Z (default: the model's centre)")
      .option("--up", o.up, "camera up vector X,Y,Z (default 0,1,0; top/bottom views use -z/+z)")
      .option("--fov", o.fov, "vertical field of view in degrees (0 = the scene's, else 45)");
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
  const CameraOverrides view = camera_overrides(a);
  // Framing depends on the image's aspect, so it is redone after --width/--height.
  if (scene.default_camera || scene.default_light || view.any()) place_camera(scene, view);
}

std::string render_intersector(const Scene& scene) {
  return scene.render.intersector.empty() ? "watertight" : scene.render.intersector;
}

}  // namespace rayvec
