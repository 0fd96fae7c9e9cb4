// Scene: everything a render needs — camera, lights, one flattened triangle mesh with per-triangle
// materials, objects and shading attributes, and the render settings. Built from a JSON scene file
// (scene_json.cpp) or a bare OBJ (load_scene), or in code by tests.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/texture.h"
#include "scene/material.h"
#include "scene/render_settings.h"
#include "geometry/triangle_mesh.h"
#include "scene/transform.h"

namespace rayvec {

struct ObjModel;
struct TextureRead;

// A pinhole camera. Image right = cross(forward, up), image up completes the frame; row 0 is the
// top row. fov_y is the full vertical field of view in degrees.
struct Camera {
  Vec3f eye{0, 0, 5};
  Vec3f look_at{0, 0, 0};
  Vec3f up{0, 1, 0};
  float fov_y = 45.0f;
  int width = 640;
  int height = 480;
};

// Point lights: `intensity` I in W/sr, irradiance I·cosθ/r² at distance r.
// Directional lights: `irradiance` E at normal incidence, travelling along `direction`
// (from the light into the scene), irradiance E·cosθ.
struct Light {
  enum class Type { point, directional } type = Type::point;
  Vec3f position{0, 0, 0};
  Vec3f direction{0, -1, 0};  // normalized by the loader
  Vec3f power{1, 1, 1};       // intensity (point) or irradiance (directional)
};

// Values a scene file sets over an object's MTL materials (same names as MTL); unset = keep.
struct MaterialOverride {
  std::optional<Vec3f> Ka, Kd, Ks, Ke, Tf;
  std::optional<float> Ns, Ni, d;
  std::optional<int> illum;
  std::optional<std::string> map_Kd;  // absolute path

  void apply(Material& m) const;
};

struct Scene {
  std::string source;  // the file it came from (for messages and image metadata)
  Camera camera;
  Vec3f background{0, 0, 0};
  Vec3f ambient{0, 0, 0};
  std::vector<Light> lights;
  RenderSettings render;

  TriangleMesh mesh;                       // every object, world space; triangle id = index
  std::vector<int32_t> triangle_material;  // per triangle, index into materials (always valid)
  std::vector<int32_t> triangle_object;    // per triangle, index of the object it came from
  std::vector<Material> materials;
  std::vector<int32_t> material_texture;  // per material, index into textures or -1
  std::vector<Texture> textures;          // linear RGB (map_Kd)
  // Corner attributes where the OBJ gives them, by index as the OBJ gives them: triangle t's
  // vertex normals are normal_table[normal_corners[t][k]] (k = 0, 1, 2) and its texture coordinates
  // uv_table[uv_corners[t][k]]; a triangle past the end of normal_corners (uv_corners), or whose
  // first index is kNoCorners, has none (normals() and uv() read them). Most meshes give neither and
  // pay nothing; a mesh with a normal at every vertex pays 12 bytes a triangle for the indices and 12
  // a normal (about 6 a triangle), where the three normals copied into every triangle cost 36.
  static constexpr uint32_t kNoCorners = 0xffffffffu;
  std::vector<std::array<uint32_t, 3>> normal_corners, uv_corners;
  std::vector<Vec3f> normal_table;
  std::vector<std::array<float, 2>> uv_table;
  // Per mesh vertex: its colour from the OBJ (`v x y z r g b`), clamped to [0, 1], which multiplies
  // the diffuse albedo; white for the vertices of objects without colours (past its end for those
  // added after the last object with them), and empty while no object has any.
  std::vector<Vec3f> vertex_colors;
  std::vector<std::string> warnings;
  // The camera and lights are rayvec's defaults (default_view.h), not the file's: a bare OBJ, or a
  // scene JSON without "camera" (default_camera) or without "lights" (default_light).
  bool default_camera = false, default_light = false;

  std::size_t object_count() const { return object_count_; }

  // Appends a model's triangles (transformed to world space) and its materials with `override`
  // applied (triangles without a material get the MTL default material, overridden too) as one
  // new object; map_Kd textures are read, the distinct new files on up to `threads` threads (one
  // that cannot be used: a warning, the material keeps Kd). The scene is the same whatever `threads`.
  void add_object(const ObjModel& model, const Transform& transform, const MaterialOverride& override = {},
                  int threads = 1);
  // Appends one triangle with material `material` (index) — for scenes built in code.
  void add_triangle(Vec3f a, Vec3f b, Vec3f c, int32_t material);
  // Gives triangle t vertex normals / texture coordinates (corners in the triangle's order).
  void set_normals(std::size_t t, const std::array<Vec3f, 3>& normals);
  void set_uv(std::size_t t, const std::array<std::array<float, 2>, 3>& uv);
  // Triangle t's vertex normals / texture coordinates (corners in the triangle's order), or none.
  std::optional<std::array<Vec3f, 3>> normals(std::size_t t) const {
    if (t >= normal_corners.size() || normal_corners[t][0] == kNoCorners) return std::nullopt;
    const auto& k = normal_corners[t];
    return std::array<Vec3f, 3>{normal_table[k[0]], normal_table[k[1]], normal_table[k[2]]};
  }
  std::optional<std::array<std::array<float, 2>, 3>> uv(std::size_t t) const {
    if (t >= uv_corners.size() || uv_corners[t][0] == kNoCorners) return std::nullopt;
    const auto& k = uv_corners[t];
    return std::array<std::array<float, 2>, 3>{uv_table[k[0]], uv_table[k[1]], uv_table[k[2]]};
  }
  // Triangle t's vertex colours (corners in the triangle's order), or none when the scene has none.
  std::optional<std::array<Vec3f, 3>> colors(std::size_t t) const {
    if (vertex_colors.empty()) return std::nullopt;
    const auto color = [&](uint32_t v) {
      return v < vertex_colors.size() ? vertex_colors[v] : Vec3f{1, 1, 1};
    };
    const auto& k = mesh.triangles[t];
    return std::array<Vec3f, 3>{color(k[0]), color(k[1]), color(k[2])};
  }
  int32_t add_material(const Material& m);

  // World-space bounds of the mesh (empty scene: a unit box at the origin).
  std::pair<Vec3f, Vec3f> bounds() const;

 private:
  int32_t add_material(const Material& m, TextureRead* read);
  std::size_t object_count_ = 0;
};

// A bare OBJ's camera and light (default_view.cpp): marks both as defaults, frames the mesh's bounding
// box from the iso view with a point light at the eye (place_camera), ambient 0.05, black background.
void frame_bounding_box(Scene& scene);

// Loads `path`: a JSON scene (.json) or a bare Wavefront OBJ (.obj, framed by frame_bounding_box).
// Throws InputError (exit 2) naming the file and the problem. `threads`: how many the loading may
// use (ObjLoadOptions::available_threads), the command's --threads.
Scene load_scene(const std::string& path, int threads = 1);
Scene load_scene_json(const std::string& path, int threads = 1);

}  // namespace rayvec
