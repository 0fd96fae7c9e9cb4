// The only file that includes tiny_obj_loader.h (Debian's libtinyobjloader: header + shared
// library, so no TINYOBJLOADER_IMPLEMENTATION here). Geometry comes from rayvec's fast reader
// (obj_fast.h) where the file allows; otherwise tinyobjloader parses, and rayvec validates first
// (obj_scan.cpp) because tinyobjloader turns `nan` into 0 and drops bad faces quietly. Both readers
// triangulate polygons by triangulate_polygon (tinyobjloader's ear clipping drops concave parts).
// Both number `usemtl` names through the same MtlReader.
#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "io/text_file.h"
#include "io/input_error.h"
#include "platform/stopwatch.h"
#include "scene/material_names.h"
#include "scene/mtl_file.h"
#include "scene/obj_fast.h"
#include "scene/obj_scan.h"
#include "scene/tinyobj_text.h"
#include "scene/polygon_triangulation.h"
#include "scene/texture_path.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

// Reads `mtllib` files relative to the OBJ's directory (names as exporters write them:
// resolve_named_file) through read_mtl_file (input limit, NUL check, validation, texture
// look-up); tinyobjloader only learns the names, to number `usemtl`.
class MtlReader : public tinyobj::MaterialReader {
 public:
  MtlReader(fs::path obj_dir, std::vector<std::string>& warnings)
      : obj_dir_(std::move(obj_dir)), warnings_(warnings) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* by_name, std::string* warn, std::string*) override {
    std::error_code ec;
    const fs::path mtl = resolve_named_file(name, obj_dir_.string());
    if (!fs::exists(mtl, ec)) {
      *warn += "material file " + mtl.string() + " not found; using default materials\n";
      return false;
    }
    // Only regular files: a stranger's `mtllib /dev/zero` (or a FIFO) would read forever.
    if (!fs::is_regular_file(mtl, ec)) {
      *warn += "material file " + mtl.string() + " is not a regular file; using default materials\n";
      return false;
    }
    return load(mtl, materials, by_name);
  }

  // Whether `name` (a whole `mtllib` line's) is a file, for mtllib_text.
  bool exists(const std::string& name) const {
    std::error_code ec;
    return fs::is_regular_file(resolve_named_file(name, obj_dir_.string()), ec);
  }

  std::vector<Material> read;  // parallel to tinyobjloader's materials

 private:
  bool load(const fs::path& mtl, std::vector<tinyobj::material_t>* materials,
            std::map<std::string, int>* by_name) {
    for (Material& m : read_mtl_file(mtl.string(), warnings_)) {
      const int index = static_cast<int>(materials->size());
      by_name->emplace(material_key(m.name), index);  // as `usemtl` lines reach tinyobjloader
      tinyobj::material_t named{};  // value-initialized: tinyobjloader leaves its members unset
      named.name = m.name;
      materials->push_back(named);
      read.push_back(std::move(m));
    }
    return true;
  }

  fs::path obj_dir_;
  std::vector<std::string>& warnings_;
};

Vec3f vec3(const tinyobj::real_t* v) { return {v[0], v[1], v[2]}; }

// tinyobjloader's warnings for `usemtl` lines whose material no MTL file loaded before them
// defines, given their line numbers: once a material is defined it stays, so the warnings for a
// key are for its first `usemtl` lines, in order.
std::string with_usemtl_lines(const std::string& warn, const std::vector<UsemtlLine>& usemtl_lines) {
  std::unordered_map<std::string, std::vector<std::size_t>> lines_of;
  for (const UsemtlLine& u : usemtl_lines) lines_of[u.key].push_back(u.line);
  std::unordered_map<std::string, std::size_t> used;
  std::istringstream in(warn);
  std::string out, key;
  for (std::string line; std::getline(in, line);) {
    std::size_t line_no = 0;
    if (parse_unknown_material(line, key, line_no) && line_no == 0) {
      const std::vector<std::size_t>& lines = lines_of[key];
      const std::size_t k = used[key]++;
      if (k < lines.size()) line = unknown_material_text(key, lines[k]);
    }
    out += line + "\n";
  }
  return out;
}

// The readers' warning text (tinyobjloader's, or the fast reader's written alike) into
// `warnings` as the user reads them. A `usemtl` whose material is missing reads
// `path:line: usemtl 'name': ...`, once per name, with the count of the later lines naming it (a
// file whose thousand `usemtl` lines name a missing material warns once); any other warning given
// more than once, once with its count. A `g` line without a name changes nothing rayvec reads: not
// a warning.
void split_warnings(const std::string& text, const std::string& path, std::vector<std::string>& warnings) {
  std::istringstream lines(text);
  struct Distinct {
    std::string text;
    bool usemtl;  // a missing material's, counted by lines
    std::size_t count;
  };
  std::vector<Distinct> distinct;
  std::unordered_map<std::string, std::size_t> at;  // where a line (or a missing material) is in `distinct`
  for (std::string line; std::getline(lines, line);) {
    // tinyobjloader repeats a missing MTL file in a second line; MtlReader already named it.
    if (line.empty() || line == "." || line.rfind("Failed to load material file", 0) == 0 ||
        line.rfind("Empty group name.", 0) == 0)
      continue;
    std::string key, id = line;
    std::size_t line_no = 0;
    const bool usemtl = parse_unknown_material(line, key, line_no);
    if (usemtl) {
      id = "usemtl\n" + key;
      line =
          (line_no > 0 ? ":" + std::to_string(line_no) : std::string()) + ": usemtl '" + material_name(key) +
          "': no MTL file loaded before it (mtllib) defines that material; drawn with the default material";
    } else {
      line = ": " + line;
    }
    const auto [it, fresh] = at.emplace(id, distinct.size());
    if (fresh)
      distinct.push_back({std::move(line), usemtl, 1});
    else
      ++distinct[it->second].count;
  }
  for (const Distinct& d : distinct) {
    const std::string more = d.count < 2 ? ""
                             : d.usemtl  ? " (and on " + std::to_string(d.count - 1) + " later lines)"
                                         : " (" + std::to_string(d.count) + " times)";
    warnings.push_back(path + d.text + more);
  }
}

// tinyobjloader's shapes into the triangles, attributes and material ids of `model`; `large`: the
// true corner counts of the faces whose count tinyobjloader wraps at 256 (check_obj_text).
void convert_geometry(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                      const std::vector<LargeFace>& large, std::size_t material_count,
                      const std::string& path, ObjModel& model) {
  const auto nv = static_cast<int>(attrib.vertices.size() / 3);
  const auto nn = static_cast<int>(attrib.normals.size() / 3);
  const auto nt = static_cast<int>(attrib.texcoords.size() / 2);
  model.mesh.positions.reserve(static_cast<std::size_t>(nv));
  for (int i = 0; i < nv; ++i) model.mesh.positions.push_back(vec3(&attrib.vertices[3 * i]));
  // tinyobjloader gives every position a colour, white where its line has none
  if (attrib.colors.size() == attrib.vertices.size() &&
      std::any_of(attrib.colors.begin(), attrib.colors.end(), [](tinyobj::real_t c) { return c != 1; })) {
    model.colors.reserve(static_cast<std::size_t>(nv));
    for (int i = 0; i < nv; ++i) model.colors.push_back(vec3(&attrib.colors[3 * i]));
  }
  for (int i = 0; i < nn; ++i) model.normals.push_back(vec3(&attrib.normals[3 * i]));
  for (int i = 0; i < nt; ++i)
    model.texcoords.push_back({attrib.texcoords[2 * i], attrib.texcoords[2 * i + 1]});

  // Shapes come out in file order (a new shape at each `o`, `g` or material change), so their
  // concatenation numbers the triangles in file order; a polygon's triangles come together, in
  // triangulate_polygon's order.
  std::vector<Vec3f> corner_positions;
  std::vector<std::array<uint32_t, 3>> split;
  std::size_t face = 0;  // among all shapes
  auto next_large = large.begin();
  const auto unexpected = [&] {
    return InputError(path, 0, "tinyobjloader returned faces rayvec did not see");
  };
  for (const tinyobj::shape_t& shape : shapes) {
    const auto& idx = shape.mesh.indices;
    std::size_t first = 0;  // index of the face's first corner
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
      std::size_t corners = shape.mesh.num_face_vertices[f];
      if (next_large != large.end() && next_large->face == face) {
        if (next_large->corners % 256 != corners) throw unexpected();
        corners = (next_large++)->corners;
      }
      if (corners < 3 || first + corners > idx.size()) throw unexpected();
      // obj_scan.cpp has checked every index with its line; this guards against surprises.
      corner_positions.clear();
      for (std::size_t k = 0; k < corners; ++k) {
        const int v = idx[first + k].vertex_index;
        if (v < 0 || v >= nv)
          throw InputError(path, 0, "tinyobjloader returned a face vertex index out of range");
        corner_positions.push_back(model.mesh.positions[static_cast<std::size_t>(v)]);
      }
      split.clear();
      triangulate_polygon(corner_positions, split);
      const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      const uint32_t smoothing =
          f < shape.mesh.smoothing_group_ids.size() ? shape.mesh.smoothing_group_ids[f] : 0;
      for (const std::array<uint32_t, 3>& corner : split) {
        std::array<uint32_t, 3> tri{};
        std::array<int32_t, 3> tri_n = kNoCornerIndices, tri_t = kNoCornerIndices;
        for (int k = 0; k < 3; ++k) {
          const tinyobj::index_t& c = idx[first + corner[k]];
          tri[k] = static_cast<uint32_t>(c.vertex_index);
          if (c.normal_index >= 0 && c.normal_index < nn) tri_n[k] = c.normal_index;
          if (c.texcoord_index >= 0 && c.texcoord_index < nt) tri_t[k] = c.texcoord_index;
        }
        model.mesh.triangles.push_back(tri);
        model.triangle_normals.push_back(tri_n);
        model.triangle_texcoords.push_back(tri_t);
        model.triangle_material.push_back(
            material >= 0 && material < static_cast<int>(material_count) ? material : -1);
        model.triangle_smoothing.push_back(smoothing);
      }
      first += corners;
    }
    if (first != idx.size()) throw unexpected();
  }
  if (next_large != large.end()) throw unexpected();
  // ObjModel: a kind no face gives leaves its array empty
  const auto drop_if_unused = [](std::vector<std::array<int32_t, 3>>& v) {
    if (std::all_of(v.begin(), v.end(), [](const auto& idx) { return idx == kNoCornerIndices; }))
      std::vector<std::array<int32_t, 3>>().swap(v);
  };
  drop_if_unused(model.triangle_normals);
  drop_if_unused(model.triangle_texcoords);
  if (std::all_of(model.triangle_smoothing.begin(), model.triangle_smoothing.end(),
                  [](uint32_t g) { return g == 0; }))
    std::vector<uint32_t>().swap(model.triangle_smoothing);
}

}  // namespace

ObjModel load_obj(const std::string& path, const ObjLoadOptions& options, ObjLoadTimes* times) {
  ObjLoadTimes clock;
  auto t0 = std::chrono::steady_clock::now();
  const TextFile file(path);
  const std::string_view text = file.text();
  clock.read = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  ObjModel model;
  MtlReader mtl_reader(fs::path(path).parent_path(), model.warnings);
  const MtlLibraries mtl{
      [&](const std::string& name) { return mtl_reader.exists(name); },
      [&](const std::string& file, std::map<std::string, int>& by_name, std::string& mtl_warn,
          std::string& mtl_err) { return mtl_reader(file, &materials, &by_name, &mtl_warn, &mtl_err); }};
  const int threads = options.threads > 0                                                   ? options.threads
                      : options.available_threads >= 2 && text.size() >= kObjTwoThreadsFrom ? 2
                                                                                            : 1;
  clock.threads = threads;
  clock.fast = !options.reference && load_obj_fast(text, threads, mtl, model, warn, err);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<LargeFace> large_faces;
  std::vector<UsemtlLine> usemtl_lines;
  if (!clock.fast) {
    const double before_check = seconds_since(t0);
    large_faces = check_obj_text(text, path);
    clock.check = seconds_since(t0) - before_check;
    std::istringstream in{text_for_tinyobjloader(text, usemtl_lines, mtl.exists)};
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &mtl_reader, false))
      throw InputError(path, 0, "cannot parse: " + err);
    warn = with_usemtl_lines(warn, usemtl_lines);
  }
  clock.parse = seconds_since(t0) - clock.check;

  t0 = std::chrono::steady_clock::now();
  split_warnings(warn, path, model.warnings);
  if (!err.empty()) split_warnings(err, path, model.warnings);  // e.g. MTL problems on success
  model.materials = std::move(mtl_reader.read);
  if (!clock.fast) convert_geometry(attrib, shapes, large_faces, materials.size(), path, model);
  clock.convert = seconds_since(t0);
  model.source = path;
  if (times) *times = clock;
  if (model.mesh.triangles.empty())
    throw InputError(path, 0, "no triangles (the file has no `f` face with 3 or more corners)");
  return model;
}

}  // namespace rayvec
