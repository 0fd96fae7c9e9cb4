// JSON scene files (docs/scenes.md lists every key). The only file that includes nlohmann/json.
// Unknown keys are errors naming the key: a typo such as "fov" for "fov_y" must not pass silently.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <vector>
#include <set>
#include <map>
#include <cstdio>
#include <filesystem>
#include <initializer_list>

#include "geometry/coordinate_range.h"
#include "io/input_error.h"
#include "kernels/intersector.h"
#include "io/text_file.h"
#include "scene/camera_check.h"
#include "scene/default_view.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Reads one JSON object with a dotted path ("lights[1].position") for messages.
class Reader {
 public:
  Reader(const std::string& file, const std::string& text) : file_(file), text_(text) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    // nlohmann keeps no positions; the first line that mentions the key is close enough.
    const std::string key = where.substr(where.find_last_of(".]") + 1);
    throw InputError(file_, line_of(key), where + ": " + what);
  }

  // Rejects any key of `object` not in `allowed`.
  void keys(const json& object, const std::string& where, std::initializer_list<const char*> allowed) const {
    if (!object.is_object()) fail(where, "expected an object {...}");
    for (const auto& [key, value] : object.items()) {
      bool known = false;
      std::string list;
      for (const char* a : allowed) {
        known = known || key == a;
        list += std::string(list.empty() ? "" : ", ") + a;
      }
      if (!known)
        throw InputError(file_, line_of(key),
                         "unknown key '" + join(where, key) + "' (allowed here: " + list + ")");
    }
  }

  float number(const json& v, const std::string& where) const {
    if (!v.is_number()) fail(where, "expected a number, got " + std::string(v.type_name()));
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > 3.0e38) fail(where, "number out of range");
    return static_cast<float>(d);
  }
  int integer(const json& v, const std::string& where, int lo, int hi) const {
    if (!v.is_number_integer() && !v.is_number_unsigned())
      fail(where, "expected an integer, got " + std::string(v.type_name()));
    const long long i = v.get<long long>();
    if (i < lo || i > hi) fail(where, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    return static_cast<int>(i);
  }
  Vec3f vec3(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() != 3) fail(where, "expected an array of 3 numbers [x, y, z]");
    return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
  }
  Vec3f colour(const json& v, const std::string& where) const {
    const Vec3f c = vec3(v, where);
    if (c.x < 0 || c.y < 0 || c.z < 0) fail(where, "colour components must be >= 0");
    return c;
  }
  std::string string(const json& v, const std::string& where) const {
    if (!v.is_string()) fail(where, "expected a string, got " + std::string(v.type_name()));
    return v.get<std::string>();
  }
  // A path relative to the scene file's directory.
  std::string path(const json& v, const std::string& where) const {
    const fs::path p = string(v, where);
    return (p.is_absolute() ? p : fs::path(file_).parent_path() / p).lexically_normal().string();
  }
  const std::string& file() const { return file_; }

  static std::string join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
  }

 private:
  std::size_t line_of(const std::string& key) const {
    const std::size_t at = text_.find("\"" + key + "\"");
    if (at == std::string::npos) return 0;
    return 1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + at, '\n'));
  }
  std::string file_, text_;
};

Camera read_camera(const Reader& r, const json& j) {
  r.keys(j, "camera", {"eye", "look_at", "up", "fov_y", "width", "height"});
  Camera c;
  if (j.contains("eye")) c.eye = r.vec3(j["eye"], "camera.eye");
  if (j.contains("look_at")) c.look_at = r.vec3(j["look_at"], "camera.look_at");
  if (j.contains("up")) c.up = r.vec3(j["up"], "camera.up");
  if (j.contains("fov_y")) c.fov_y = r.number(j["fov_y"], "camera.fov_y");
  if (j.contains("width")) c.width = r.integer(j["width"], "camera.width", 1, 16384);
  if (j.contains("height")) c.height = r.integer(j["height"], "camera.height", 1, 16384);
  if (const std::optional<CameraProblem> p = camera_problem(c)) {
    constexpr const char* kKey[] = {"camera.eye", "camera.look_at", "camera.up", "camera.fov_y"};
    r.fail(kKey[static_cast<int>(p->field)], p->what);
  }
  return c;
}

Light read_light(const Reader& r, const json& j, const std::string& where) {
  r.keys(j, where, {"type", "position", "intensity", "direction", "irradiance"});
  if (!j.contains("type")) r.fail(where + ".type", "missing (\"point\" or \"directional\")");
  const std::string type = r.string(j["type"], where + ".type");
  Light light;
  if (type == "point") {
    for (const char* k : {"direction", "irradiance"})
      if (j.contains(k)) r.fail(Reader::join(where, k), "belongs to directional lights");
    if (!j.contains("position")) r.fail(where + ".position", "missing");
    light.position = r.vec3(j["position"], where + ".position");
    if (!point_in_range(light.position))
      r.fail(where + ".position", std::string("is beyond ") + kCoordinateRangeText);
    if (j.contains("intensity")) light.power = r.colour(j["intensity"], where + ".intensity");
  } else if (type == "directional") {
    light.type = Light::Type::directional;
    for (const char* k : {"position", "intensity"})
      if (j.contains(k)) r.fail(Reader::join(where, k), "belongs to point lights");
    if (!j.contains("direction")) r.fail(where + ".direction", "missing");
    const Vec3f d = r.vec3(j["direction"], where + ".direction");
    const float size = largest_component(d);
    if (!(size > 0)) r.fail(where + ".direction", "must not be zero");
    if (!(size >= kMinDirection && size <= kMaxDirection))
      r.fail(where + ".direction",
             "needs its largest component between 1e-6 and 1e16 in magnitude (its length does not matter)");
    light.direction = normalize(d);
    if (j.contains("irradiance")) light.power = r.colour(j["irradiance"], where + ".irradiance");
  } else {
    r.fail(where + ".type", "unknown light type '" + type + "' (choose point or directional)");
  }
  return light;
}

Transform read_transform(const Reader& r, const json& j, const std::string& where) {
  r.keys(j, where, {"scale", "rotate_deg", "translate"});
  Transform t;
  if (j.contains("scale")) {
    const json& s = j["scale"];
    t.scale = s.is_number() ? Vec3f{1, 1, 1} * r.number(s, where + ".scale") : r.vec3(s, where + ".scale");
    if (t.scale.x == 0 || t.scale.y == 0 || t.scale.z == 0) r.fail(where + ".scale", "must not be 0");
  }
  if (j.contains("rotate_deg")) t.rotate_deg = r.vec3(j["rotate_deg"], where + ".rotate_deg");
  if (j.contains("translate")) t.translate = r.vec3(j["translate"], where + ".translate");
  return t;
}

MaterialOverride read_material(const Reader& r, const json& j, const std::string& where) {
  r.keys(j, where, {"Ka", "Kd", "Ks", "Ke", "Tf", "Ns", "Ni", "d", "illum", "map_Kd"});
  MaterialOverride m;
  auto col = [&](const char* k, std::optional<Vec3f>& out) {
    if (j.contains(k)) out = r.colour(j[k], Reader::join(where, k));
  };
  col("Ka", m.Ka);
  col("Kd", m.Kd);
  col("Ks", m.Ks);
  col("Ke", m.Ke);
  col("Tf", m.Tf);
  if (j.contains("Ns")) m.Ns = r.number(j["Ns"], where + ".Ns");
  if (j.contains("Ni")) m.Ni = r.number(j["Ni"], where + ".Ni");
  if (j.contains("d")) m.d = r.number(j["d"], where + ".d");
  if (j.contains("illum")) m.illum = r.integer(j["illum"], where + ".illum", 0, 10);
  if (j.contains("map_Kd")) m.map_Kd = r.path(j["map_Kd"], where + ".map_Kd");
  if (m.Ns && *m.Ns < 0) r.fail(where + ".Ns", "must be >= 0");
  if (m.Ni && !(*m.Ni > 0)) r.fail(where + ".Ni", "must be > 0");
  if (m.d && !(*m.d >= 0 && *m.d <= 1)) r.fail(where + ".d", "must be between 0 and 1");
  return m;
}

RenderSettings read_render(const Reader& r, const json& j) {
  r.keys(j, "render", {"max_depth", "min_contribution", "spp", "intersector"});
  RenderSettings s;
  if (j.contains("max_depth")) s.max_depth = r.integer(j["max_depth"], "render.max_depth", 0, 64);
  if (j.contains("min_contribution")) {
    s.min_contribution = r.number(j["min_contribution"], "render.min_contribution");
    if (!(s.min_contribution >= 0 && s.min_contribution <= 1))
      r.fail("render.min_contribution", "must be between 0 and 1");
  }
  if (j.contains("spp")) s.spp = r.integer(j["spp"], "render.spp", 1, 4096);
  if (j.contains("intersector")) {
    s.intersector = r.string(j["intersector"], "render.intersector");
    if (!parse_intersector(s.intersector))
      r.fail("render.intersector",
             "unknown '" + s.intersector + "' (choose mt, mt64, paper, watertight or watertight64)");
  }
  return s;
}

}  // namespace

// nlohmann keeps the last of two equal keys in an object; a scene with two "width"s is a mistake the
// user should hear about. Keys are seen in text order, so the n-th `"key":` in the text is the
// n-th key event of that name: that gives the duplicate's line.
class DuplicateKeys {
 public:
  json::parser_callback_t callback() {
    return [this](int, json::parse_event_t event, json& parsed) {
      if (event == json::parse_event_t::object_start) {
        keys_.emplace_back();
        path_.emplace_back();
      } else if (event == json::parse_event_t::object_end && !keys_.empty()) {
        keys_.pop_back();
        path_.pop_back();
      } else if (event == json::parse_event_t::key && !keys_.empty()) {
        const std::string key = parsed.get<std::string>();
        const int n = ++seen_[key];
        path_.back() = key;
        if (!keys_.back().insert(key).second && first_.empty()) {
          for (const std::string& k : path_) first_ += (first_.empty() ? "" : ".") + k;
          occurrence_ = n;
          key_ = key;
        }
      }
      return true;
    };
  }

  void report(const std::string& file, const std::string& text) const {
    if (first_.empty()) return;
    std::size_t line = 0;
    int n = 0;
    const std::string quoted = "\"" + key_ + "\"";
    for (std::size_t at = text.find(quoted); at != std::string::npos; at = text.find(quoted, at + 1)) {
      std::size_t after = at + quoted.size();
      while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
      if (after < text.size() && text[after] == ':' && ++n == occurrence_) {
        line = 1 + std::count(text.begin(), text.begin() + at, '\n');
        break;
      }
    }
    throw InputError(file, line,
                     "duplicate key '" + first_ + "' (a JSON object holds one value per key; remove one)");
  }

 private:
  std::vector<std::set<std::string>> keys_;
  std::vector<std::string> path_;
  std::map<std::string, int> seen_;
  std::string first_, key_;
  int occurrence_ = 0;
};

Scene load_scene_json(const std::string& path, int threads) {
  const std::string text = read_text_file(path);  // bounded; rejects binary data and UTF-16
  json root;
  try {
    DuplicateKeys dup;
    root = json::parse(text, dup.callback());
    dup.report(path, text);
  } catch (const json::parse_error& e) {
    const std::size_t byte = std::min<std::size_t>(e.byte, text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + byte, '\n');
    std::string what = e.what();
    what = what.substr(what.find(':') != std::string::npos ? what.rfind(':') + 2 : 0);
    throw InputError(path, std::size_t(line), "invalid JSON: " + what);
  } catch (const json::exception& e) {
    // e.g. out_of_range 406 "number overflow parsing '1e999'" (found by fuzz_scene_json): no byte
    // position, so point at the line of the quoted text.
    std::string what = e.what();
    what = what.substr(what.find(']') != std::string::npos ? what.find(']') + 2 : 0);
    const std::size_t q = what.find('\''), q2 = what.rfind('\'');
    std::size_t line = 0;
    if (q != std::string::npos && q2 > q) {
      const std::size_t at = text.find(what.substr(q + 1, q2 - q - 1));
      if (at != std::string::npos) line = 1 + std::count(text.begin(), text.begin() + at, '\n');
    }
    throw InputError(path, line, "invalid JSON: " + what);
  }
  const Reader r(path, text);
  r.keys(root, "", {"camera", "background", "ambient", "lights", "objects", "render", "comment"});

  Scene scene;
  scene.source = path;
  if (root.contains("camera")) scene.camera = read_camera(r, root["camera"]);
  if (root.contains("background")) scene.background = r.colour(root["background"], "background");
  if (root.contains("ambient")) scene.ambient = r.colour(root["ambient"], "ambient");
  if (root.contains("render")) scene.render = read_render(r, root["render"]);
  if (root.contains("lights")) {
    if (!root["lights"].is_array()) r.fail("lights", "expected an array of lights");
    for (std::size_t i = 0; i < root["lights"].size(); ++i)
      scene.lights.push_back(read_light(r, root["lights"][i], "lights[" + std::to_string(i) + "]"));
  }
  if (!root.contains("objects") || !root["objects"].is_array() || root["objects"].empty())
    r.fail("objects", "expected a non-empty array of objects ({\"obj\": \"file.obj\"})");
  for (std::size_t i = 0; i < root["objects"].size(); ++i) {
    const std::string where = "objects[" + std::to_string(i) + "]";
    const json& o = root["objects"][i];
    r.keys(o, where, {"obj", "transform", "material"});
    if (!o.contains("obj")) r.fail(where + ".obj", "missing (path of a Wavefront OBJ file)");
    const std::string obj = r.path(o["obj"], where + ".obj");
    const Transform t =
        o.contains("transform") ? read_transform(r, o["transform"], where + ".transform") : Transform{};
    const MaterialOverride m =
        o.contains("material") ? read_material(r, o["material"], where + ".material") : MaterialOverride{};
    const std::size_t first_vertex = scene.mesh.positions.size();
    scene.add_object(load_obj(obj, ObjLoadOptions{.available_threads = threads}), t, m, threads);
    for (std::size_t v = first_vertex; v < scene.mesh.positions.size(); ++v)
      if (!point_in_range(scene.mesh.positions[v])) {
        const Vec3f p = scene.mesh.positions[v];
        char at[96];
        std::snprintf(at, sizeof at, "(%g, %g, %g)", double(p.x), double(p.y), double(p.z));
        r.fail(where + ".transform",
               "moves a vertex of " + obj + " to " + at + ", beyond " + kCoordinateRangeText);
      }
  }
  // Without a camera or lights, rayvec's defaults (default_view.h), as for a bare OBJ.
  scene.default_camera = !root.contains("camera");
  scene.default_light = !root.contains("lights");
  if (scene.default_camera || scene.default_light) place_camera(scene);
  return scene;
}

namespace {

// Secondary rays start off their surface by offset_ray_origin(), whose absolute offset near the
// origin (1/65536) is tested for scenes from 1e-4 across up (offset_ray_test.cpp); in a smaller
// scene it would move every shadow and reflection ray out of the scene.
constexpr float kMinSceneSize = 1e-4f;

Scene checked_size(Scene scene, const std::string& path) {
  const auto [lo, hi] = scene.bounds();
  const float size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (size == 0)
    throw InputError(path, 0,
                     "the scene's triangles all lie at one point (0 across): there is nothing to render");
  if (size < kMinSceneSize) {
    char text[160];
    std::snprintf(text, sizeof text, "the scene is %g across, below %g, the smallest size rayvec renders",
                  double(size), double(kMinSceneSize));
    throw InputError(
        path, 0,
        std::string(text) +
            " (secondary-ray offsets would leave it); scale it up with a scene JSON "
            "transform, e.g. {\"objects\": [{\"obj\": \"m.obj\", \"transform\": {\"scale\": 1e6}}]}");
  }
  return scene;
}

}  // namespace

Scene load_scene(const std::string& path, int threads) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".json") return checked_size(load_scene_json(path, threads), path);
  if (ext == ".obj") {
    Scene scene;
    scene.source = path;
    scene.add_object(load_obj(path, ObjLoadOptions{.available_threads = threads}), Transform{}, {}, threads);
    scene = checked_size(std::move(scene), path);
    frame_bounding_box(scene);
    return scene;
  }
  throw InputError(path, 0, "unknown scene type '" + ext + "' (give a .json scene or an .obj model)");
}

}  // namespace rayvec
