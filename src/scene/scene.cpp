#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <unordered_map>

#include "platform/large_buffer.h"
#include "scene/obj_loader.h"
#include "scene/smooth_normals.h"
#include "scene/texture_reads.h"

namespace rayvec {
namespace {

// Room for `count` elements in one allocation when `v` has less (at least doubling, so adding many
// small objects stays linear), advised for huge pages: growing a million-triangle scene's arrays
// element by element copied each one about once more and faulted in twice the pages. (Room only:
// an OBJ's normals may cover some of its triangles, and pages never written are never faulted in.)
template <typename T>
void make_room(std::vector<T>& v, std::size_t count) {
  if (v.capacity() >= count) return;
  v.reserve(std::max(count, 2 * v.capacity()));
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace

void MaterialOverride::apply(Material& m) const {
  if (Ka) m.Ka = *Ka;
  if (Kd) m.Kd = *Kd;
  if (Ks) m.Ks = *Ks;
  if (Ke) m.Ke = *Ke;
  if (Tf) m.Tf = *Tf;
  if (Ns) m.Ns = *Ns;
  if (Ni) m.Ni = *Ni;
  if (d) m.d = *d;
  if (illum) m.illum = *illum;
  if (map_Kd) {  // the scene's texture, without the MTL's scale and offset for the one it replaces
    m.map_Kd = *map_Kd;
    m.map_Kd_scale = {1, 1};
    m.map_Kd_offset = {0, 0};
  }
}

int32_t Scene::add_material(const Material& m) { return add_material(m, nullptr); }

// The texture a new material names: one already loaded for an earlier material (one texture per
// distinct file), else `read` when the file was read ahead (add_object), else read now.
int32_t Scene::add_material(const Material& m, TextureRead* read) {
  materials.push_back(m);
  int32_t texture = -1;
  if (!m.map_Kd.empty()) {
    for (std::size_t i = 0; i < materials.size() - 1; ++i)
      if (materials[i].map_Kd == m.map_Kd) texture = material_texture[i];
    if (texture < 0) {
      TextureRead now;
      if (!read) now = read_texture_file(m.map_Kd);
      TextureRead& r = read ? *read : now;
      if (r.failure) std::rethrow_exception(r.failure);
      // A texture that cannot be used leaves the material with Kd alone: a warning, not a failure
      // (`render --strict` makes it one).
      const std::string& problem = r.problem;
      if (problem.empty()) {
        textures.push_back(std::move(r.texture));
        texture = static_cast<int32_t>(textures.size() - 1);
      } else {
        warnings.push_back("material '" + m.name + "': texture " + m.map_Kd + " " + problem +
                           "; drawn with Kd only");
        materials.back().map_Kd.clear();
      }
    }
  }
  material_texture.push_back(texture);
  return static_cast<int32_t>(materials.size() - 1);
}

void Scene::add_triangle(Vec3f a, Vec3f b, Vec3f c, int32_t material) {
  mesh.add_triangle(a, b, c);
  triangle_material.push_back(material);
  triangle_object.push_back(static_cast<int32_t>(object_count_));
}

namespace {

// Slot t of per-triangle corner indices, the triangles before it without any.
std::array<uint32_t, 3>& corner_slot(std::vector<std::array<uint32_t, 3>>& corners, std::size_t t) {
  if (corners.size() <= t) corners.resize(t + 1, {Scene::kNoCorners, Scene::kNoCorners, Scene::kNoCorners});
  return corners[t];
}

// Shading normals for the object's triangles from `first_tri` on that its OBJ puts in a smoothing
// group without giving them normals (smooth_normals.h), from the scene's transformed positions: a
// non-uniform scale changes the angles that weight them.
void add_smooth_normals(Scene& scene, const ObjModel& model, std::size_t first_tri) {
  const std::vector<uint32_t>& group = model.triangle_smoothing;
  if (group.size() != model.mesh.size()) return;  // none (ObjModel: empty without groups)
  std::vector<uint32_t> wanted;
  for (std::size_t t = 0; t < group.size(); ++t) {
    const std::size_t tri = first_tri + t;
    const bool has_normals =
        tri < scene.normal_corners.size() && scene.normal_corners[tri][0] != Scene::kNoCorners;
    if (group[t] != 0 && !has_normals) wanted.push_back(static_cast<uint32_t>(t));
  }
  if (wanted.empty()) return;
  const std::span<const std::array<uint32_t, 3>> triangles(scene.mesh.triangles.data() + first_tri,
                                                           group.size());
  const SmoothedNormals smooth = smooth_normals(scene.mesh.positions, triangles, group, wanted);
  const auto first = static_cast<uint32_t>(scene.normal_table.size());
  scene.normal_table.insert(scene.normal_table.end(), smooth.normals.begin(), smooth.normals.end());
  make_room(scene.normal_corners, first_tri + group.size());
  corner_slot(scene.normal_corners, first_tri + group.size() - 1);  // every slot of the object at once
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    const auto& c = smooth.corners[i];
    if (c[0] != kNoSmoothNormal)
      scene.normal_corners[first_tri + wanted[i]] = {first + c[0], first + c[1], first + c[2]};
  }
}

}  // namespace

void Scene::set_normals(std::size_t t, const std::array<Vec3f, 3>& normals) {
  const auto first = static_cast<uint32_t>(normal_table.size());
  normal_table.insert(normal_table.end(), normals.begin(), normals.end());
  corner_slot(normal_corners, t) = {first, first + 1, first + 2};
}

void Scene::set_uv(std::size_t t, const std::array<std::array<float, 2>, 3>& uv) {
  const auto first = static_cast<uint32_t>(uv_table.size());
  uv_table.insert(uv_table.end(), uv.begin(), uv.end());
  corner_slot(uv_corners, t) = {first, first + 1, first + 2};
}

void Scene::add_object(const ObjModel& model, const Transform& transform, const MaterialOverride& override,
                       int threads) {
  const AffineMap map(transform);
  const auto first_material = static_cast<int32_t>(materials.size());
  std::vector<Material> object_materials(model.materials);
  for (Material& m : object_materials) override.apply(m);
  // The texture files no material has loaded yet, each once, read ahead together: a model with
  // dozens of maps spends most of its load decoding them.
  std::unordered_map<std::string, std::size_t> ahead;
  std::vector<std::string> paths;
  for (const Material& m : object_materials) {
    const bool loaded = std::any_of(materials.begin(), materials.end(),
                                    [&](const Material& earlier) { return earlier.map_Kd == m.map_Kd; });
    if (!m.map_Kd.empty() && !loaded && ahead.emplace(m.map_Kd, paths.size()).second)
      paths.push_back(m.map_Kd);
  }
  std::vector<TextureRead> reads = read_texture_files(paths, threads);
  for (const Material& m : object_materials) {
    const auto at = ahead.find(m.map_Kd);
    add_material(m, at == ahead.end() ? nullptr : &reads[at->second]);
  }
  int32_t fallback = -1;  // the MTL default, for triangles the OBJ gives no material
  const std::size_t first_tri = mesh.size(), tris = first_tri + model.mesh.size();
  // Shared vertices stay shared: each vertex a triangle uses is transformed once and stored once,
  // in the order of first use (a vertex no triangle uses is left out, so the scene's bounds and
  // default view are those of its triangles). Stored per corner, a million-triangle mesh held six
  // copies of each vertex (36 bytes a triangle instead of about 6) and transformed each six times.
  make_room(mesh.positions,
            mesh.positions.size() + std::min(model.mesh.positions.size(), 3 * model.mesh.size()));
  make_room(mesh.triangles, tris);
  make_room(triangle_material, tris);
  make_room(triangle_object, tris);
  // the OBJ's normals and texture coordinates (normals transformed) join the tables as they are;
  // the triangles index them
  const auto first_normal = static_cast<uint32_t>(normal_table.size());
  const auto first_uv = static_cast<uint32_t>(uv_table.size());
  if (!model.triangle_normals.empty()) {
    make_room(normal_table, normal_table.size() + model.normals.size());
    for (const Vec3f& n : model.normals) normal_table.push_back(map.normal(n));
    make_room(normal_corners, first_tri + model.triangle_normals.size());
  }
  if (!model.triangle_texcoords.empty()) {
    uv_table.insert(uv_table.end(), model.texcoords.begin(), model.texcoords.end());
    make_room(uv_corners, first_tri + model.triangle_texcoords.size());
  }
  constexpr uint32_t kUnplaced = 0xffffffffu;
  std::vector<uint32_t> placed(model.mesh.positions.size(), kUnplaced);
  const bool colored = !model.colors.empty() && model.colors.size() == model.mesh.positions.size();
  const auto unit_interval = [](float x) { return x >= 0 ? std::min(x, 1.0f) : 0.0f; };  // NaN: 0
  float brightest = 0;  // of the colours of the vertices the triangles use
  if (colored) {
    vertex_colors.resize(mesh.positions.size(), Vec3f{1, 1, 1});  // the objects before: white
    make_room(vertex_colors, mesh.positions.capacity());
  }
  const auto vertex = [&](uint32_t i) {
    if (placed[i] == kUnplaced) {
      placed[i] = static_cast<uint32_t>(mesh.positions.size());
      // + 0 turns −0 into +0 as point()'s double arithmetic does
      const Vec3f p = model.mesh.positions[i];
      mesh.positions.push_back(map.is_identity() ? p + Vec3f{0, 0, 0} : map.point(p));
      if (colored) {
        const Vec3f c = model.colors[i];
        vertex_colors.push_back({unit_interval(c.x), unit_interval(c.y), unit_interval(c.z)});
        brightest = std::max({brightest, c.x, c.y, c.z});
      }
    }
    return placed[i];
  };
  // A mirroring transform reverses winding; swap two corners so normals stay outward.
  const int c1 = map.flips_orientation() ? 2 : 1, c2 = map.flips_orientation() ? 1 : 2;
  const int corner[3] = {0, c1, c2};
  for (std::size_t t = 0; t < model.mesh.size(); ++t) {
    int32_t material = t < model.triangle_material.size() ? model.triangle_material[t] : -1;
    if (material >= 0 && material < int32_t(model.materials.size())) {
      material += first_material;
    } else {
      if (fallback < 0) {
        Material m;
        override.apply(m);
        fallback = add_material(m);
      }
      material = fallback;
    }
    const auto& source = model.mesh.triangles[t];
    const uint32_t a = vertex(source[0]), b = vertex(source[c1]), c = vertex(source[c2]);
    mesh.triangles.push_back({a, b, c});
    triangle_material.push_back(material);
    triangle_object.push_back(static_cast<int32_t>(object_count_));
    const std::size_t tri = first_tri + t;
    if (t < model.triangle_normals.size()) {
      const auto& idx = model.triangle_normals[t];
      if (idx[0] >= 0 && idx[1] >= 0 && idx[2] >= 0)
        corner_slot(normal_corners, tri) = {first_normal + uint32_t(idx[corner[0]]),
                                            first_normal + uint32_t(idx[corner[1]]),
                                            first_normal + uint32_t(idx[corner[2]])};
    }
    if (t < model.triangle_texcoords.size()) {
      const auto& idx = model.triangle_texcoords[t];
      if (idx[0] >= 0 && idx[1] >= 0 && idx[2] >= 0)
        corner_slot(uv_corners, tri) = {first_uv + uint32_t(idx[corner[0]]),
                                        first_uv + uint32_t(idx[corner[1]]),
                                        first_uv + uint32_t(idx[corner[2]])};
    }
  }
  add_smooth_normals(*this, model, first_tri);
  if (brightest > 1) {
    char largest[32];
    std::snprintf(largest, sizeof largest, "%g", brightest);
    warnings.push_back((model.source.empty() ? "" : model.source + ": ") + "vertex colours above 1 (up to " +
                       largest + ") are clamped to 1: OBJ colours run from 0 to 1" +
                       (brightest > 2 ? " (divide colours written as 0..255 by 255)" : ""));
  }
  warnings.insert(warnings.end(), model.warnings.begin(), model.warnings.end());
  ++object_count_;
}

std::pair<Vec3f, Vec3f> Scene::bounds() const {
  if (mesh.positions.empty()) return {{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}};
  Vec3f lo = mesh.positions[0], hi = lo;
  for (const Vec3f& p : mesh.positions) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  return {lo, hi};
}

}  // namespace rayvec
