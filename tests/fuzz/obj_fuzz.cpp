// Fuzzes the OBJ/MTL path: rayvec's fast reader (obj_chunk.cpp, obj_fast.cpp, in 2 pieces so that
// indices cross pieces) and the reference path (check_obj_text + tinyobjloader + load_obj's
// conversion), and checks that both give the same result: the same InputError message, or the same
// triangles, attribute indices, materials and warnings with coordinates within one float step. The
// input is an OBJ file, optionally followed by a line `#--mtl--` and the text of m.mtl (which the
// OBJ can pull in with `mtllib m.mtl`). The fast reader's model is then added to a scene (smooth
// normals for smoothing groups, vertex colours), whose normals and colours must be well formed. The
// only acceptable failure is InputError; any other exception, crash, sanitizer report, hang or
// difference between the two paths is a bug.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "io/input_error.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "scene/transform.h"

namespace {

struct Outcome {
  rayvec::ObjModel model;
  std::string error;  // "" when it loaded
};

Outcome load(const std::string& path, const rayvec::ObjLoadOptions& options) {
  Outcome out;
  rayvec::ObjLoadTimes times;
  try {
    out.model = rayvec::load_obj(path, options, &times);
    // the reference load must not be the fast reader, or the two loads compare it with itself
    if (options.reference && times.fast) __builtin_trap();
    const rayvec::ObjModel& model = out.model;
    // What the loader promises: every triangle corner is a valid vertex index.
    for (const auto& t : model.mesh.triangles)
      for (uint32_t i : t)
        if (i >= model.mesh.positions.size()) __builtin_trap();
    if (model.triangle_material.size() != model.mesh.triangles.size()) __builtin_trap();
    // ... and every corner's normal and texture coordinate index is -1 (none) or a valid one.
    const auto check_corners = [&](const auto& corners, std::size_t count) {
      if (!corners.empty() && corners.size() != model.mesh.triangles.size()) __builtin_trap();
      for (const auto& c : corners)
        for (int32_t i : c)
          if (i < -1 || (i >= 0 && std::size_t(i) >= count)) __builtin_trap();
    };
    check_corners(model.triangle_normals, model.normals.size());
    check_corners(model.triangle_texcoords, model.texcoords.size());
    for (int32_t m : model.triangle_material)
      if (m < -1 || (m >= 0 && std::size_t(m) >= model.materials.size())) __builtin_trap();
    // ... and every position, normal and texture coordinate is finite (obj_scan rejects nan/inf
    // text that tinyobjloader reads).
    if (!model.colors.empty() && model.colors.size() != model.mesh.positions.size()) __builtin_trap();
    for (const auto* points : {&model.mesh.positions, &model.normals, &model.colors})
      for (const rayvec::Vec3f& p : *points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
    for (const auto& t : model.texcoords)
      if (!std::isfinite(t[0]) || !std::isfinite(t[1])) __builtin_trap();
  } catch (const rayvec::InputError& e) {
    out.error = e.what();
    // load_obj's own guards behind obj_scan: reaching them means the scan missed a bad face and
    // the user got a message without a line number.
    if (out.error.find("after triangulation") != std::string::npos ||
        out.error.find("tinyobjloader returned") != std::string::npos)
      __builtin_trap();
  }
  return out;
}

// tinyobjloader's decimal conversion is not correctly rounded: one float step apart is the same.
bool close(float a, float b) {
  if (a == b) return true;
  const auto ia = std::bit_cast<int32_t>(a), ib = std::bit_cast<int32_t>(b);
  return (ia < 0) == (ib < 0) && std::abs(int64_t(ia) - int64_t(ib)) <= 1;
}

template <typename Points>
bool close(const Points& a, const Points& b, int dims) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < dims; ++k)
      if (!close(a[i][k], b[i][k])) return false;
  return true;
}

// Every position's colour, white where the model has none (the reference path cannot tell a file
// without colours from one whose colours are all white).
std::vector<rayvec::Vec3f> colors_of(const rayvec::ObjModel& m) {
  return m.colors.empty() ? std::vector<rayvec::Vec3f>(m.mesh.positions.size(), rayvec::Vec3f{1, 1, 1})
                          : m.colors;
}

// The model as a scene object, mirrored and scaled unevenly: every shading normal (from the file or
// from smoothing groups) must be a finite unit vector and every vertex colour within [0, 1].
void check_scene_object(rayvec::ObjModel model) {
  for (rayvec::Material& m : model.materials) m.map_Kd.clear();  // no texture files to read
  rayvec::Transform transform;
  transform.scale = {2, 1, -0.5f};
  rayvec::Scene scene;
  scene.add_object(model, transform);
  for (std::size_t t = 0; t < scene.mesh.size(); ++t) {
    // a file's normal is any finite vector (the shading normalizes it); a smoothed one is a unit one
    const bool from_file = t < model.triangle_normals.size() && model.triangle_normals[t][0] >= 0 &&
                           model.triangle_normals[t][1] >= 0 && model.triangle_normals[t][2] >= 0;
    if (const auto normals = scene.normals(t))
      for (const rayvec::Vec3f& n : *normals) {
        const float len = rayvec::length(n);
        if (!std::isfinite(len) || (!from_file && std::fabs(len - 1) > 1e-5f)) __builtin_trap();
      }
    if (const auto colors = scene.colors(t))
      for (const rayvec::Vec3f& c : *colors)
        for (int k = 0; k < 3; ++k)
          if (!(c[k] >= 0 && c[k] <= 1)) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSplit = "#--mtl--";
  const std::size_t split = input.find(kSplit);
  const std::string_view obj = input.substr(0, split);
  const std::string_view mtl =
      split == std::string_view::npos ? std::string_view() : input.substr(split + kSplit.size());
  rayvec::fuzz::write_scratch("m.mtl", mtl);
  const std::string path = rayvec::fuzz::write_scratch("m.obj", obj);
  const Outcome fast = load(path, {.threads = 2});
  const Outcome ref = load(path, {.reference = true});
  const rayvec::ObjModel &a = fast.model, &b = ref.model;
  if (fast.error != ref.error || a.mesh.triangles != b.mesh.triangles ||
      a.triangle_normals != b.triangle_normals || a.triangle_texcoords != b.triangle_texcoords ||
      a.triangle_material != b.triangle_material || a.triangle_smoothing != b.triangle_smoothing ||
      a.warnings != b.warnings || a.materials.size() != b.materials.size() ||
      !close(a.mesh.positions, b.mesh.positions, 3) || !close(a.normals, b.normals, 3) ||
      !close(colors_of(a), colors_of(b), 3) || !close(a.texcoords, b.texcoords, 2))
    __builtin_trap();
  if (fast.error.empty()) check_scene_object(fast.model);
  return 0;
}
