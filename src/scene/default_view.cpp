#include "scene/default_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/input_error.h"
#include "rays/pinhole_camera.h"
#include "scene/camera_check.h"

namespace rayvec {
namespace {

constexpr const char* kNames[] = {"iso", "front", "back", "left", "right", "top", "bottom"};

BBox scene_box(const Scene& scene) {
  const auto [lo, hi] = scene.bounds();
  return BBox{lo, hi};
}

// The eye's distance to the box (0 inside it).
float distance_to_box(Vec3f p, const BBox& box) {
  const Vec3f q = max(box.lo, min(p, box.hi));
  return length(p - q);
}

Vec3f default_up(Vec3f toward_eye) {
  if (std::abs(toward_eye.y) < 0.99f) return {0, 1, 0};
  return toward_eye.y > 0 ? Vec3f{0, 0, -1} : Vec3f{0, 0, 1};  // top: front at the image's bottom
}

void check_camera(const Camera& c) {
  const std::optional<CameraProblem> p = camera_problem(c);
  if (!p) return;
  constexpr const char* kOption[] = {"--eye", "--look-at", "--up", "--fov"};
  throw InputError(std::string(kOption[static_cast<int>(p->field)]) + ": " + p->what);
}

}  // namespace

View parse_view(const std::string& name) {
  for (int i = 0; i < 7; ++i)
    if (name == kNames[i]) return static_cast<View>(i);
  throw InputError("--view: unknown view '" + name +
                   "' (choose iso, front, back, left, right, top or bottom)");
}

const char* view_name(View view) { return kNames[static_cast<int>(view)]; }

namespace {

// The 3/4 view from the right of the front (+z, +x) or of one of the other three sides, above.
Vec3f quadrant_direction(int quadrant, const BBox& box) {
  const float deg = std::numbers::pi_v<float> / 180.0f;
  const float azimuth = (35.0f + 90.0f * float(quadrant)) * deg, elevation = 25.0f * deg;
  Vec3f d{std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
          std::cos(azimuth) * std::cos(elevation)};
  const Vec3f e = box.extent();
  const float largest = std::max({e.x, e.y, e.z});
  for (int a = 0; a < 3; ++a)  // flat along a: look at its face
    if (largest > 0 && e[a] < 0.1f * largest) d[a] = std::copysign(1.5f, d[a]);
  return normalize(d);
}

// How much of the mesh `toward_eye` shows, occlusion ignored: the projected area of its front sides
// (counter-clockwise, as OBJ winds outward) plus half that of its back sides. The same from every
// side for a closed mesh; larger from the open side of a room or a box, from the front of a
// single-sided plane, and from wherever a tilted plane is seen most squarely.
float shown_area(const TriangleMesh& mesh, Vec3f toward_eye) {
  double sum = 0;
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const Vec3f n = cross(mesh.vertex(t, 1) - mesh.vertex(t, 0), mesh.vertex(t, 2) - mesh.vertex(t, 0));
    const double c = dot(n, toward_eye);
    sum += c > 0 ? c : -0.5 * c;
  }
  return float(sum);
}

}  // namespace

Vec3f view_direction(View view, const BBox& box, const TriangleMesh& mesh) {
  switch (view) {
    case View::front: return {0, 0, 1};
    case View::back: return {0, 0, -1};
    case View::right: return {1, 0, 0};
    case View::left: return {-1, 0, 0};
    case View::top: return {0, 1, 0};
    case View::bottom: return {0, -1, 0};
    case View::iso: break;
  }
  // Front-right unless another side shows clearly more (5 %: a closed mesh's sides tie).
  Vec3f best = quadrant_direction(0, box);
  float best_area = shown_area(mesh, best);
  for (int q = 1; q < 4; ++q) {
    const Vec3f d = quadrant_direction(q, box);
    const float area = shown_area(mesh, d);
    if (area > 1.05f * best_area) best = d, best_area = area;
  }
  return best;
}

void place_camera(Scene& scene, const CameraOverrides& o) {
  Camera& cam = scene.camera;
  const BBox box = scene_box(scene);
  if (o.fov_y) cam.fov_y = *o.fov_y;
  if (!(cam.fov_y > 0 && cam.fov_y < 180)) throw InputError("--fov: must be between 0 and 180 degrees");
  const bool frame = scene.default_camera || o.view;
  if (frame) {
    const Vec3f toward_eye = view_direction(o.view.value_or(View::iso), box, scene.mesh);
    const Vec3f center = box.center();
    const Vec3f up = default_up(toward_eye);
    const PinholeFrame<float> f = look_at_frame(center + toward_eye, center, up);
    const float tan_y = std::tan(0.5f * cam.fov_y * std::numbers::pi_v<float> / 180.0f);
    const float tan_x = tan_y * float(cam.width) / float(cam.height);
    const float distance =
        fit_points_distance(scene.mesh.positions.data(), scene.mesh.positions.size(), center, f, toward_eye,
                            tan_x, tan_y, 1.05f, std::max(1e-3f * length(box.extent()), 1e-30f));
    cam.look_at = center;
    cam.eye = center + toward_eye * distance;
    cam.up = up;
  }
  if (o.eye) cam.eye = *o.eye;
  if (o.look_at) cam.look_at = *o.look_at;
  if (o.up) cam.up = *o.up;
  if (o.any()) check_camera(cam);

  if (scene.default_light) {
    const float diagonal = length(box.extent());
    const float near = std::max({distance_to_box(cam.eye, box), 0.05f * diagonal, 1e-30f});
    const float intensity = std::numbers::pi_v<float> * near * near;
    scene.lights = {Light{Light::Type::point, cam.eye, {0, -1, 0}, Vec3f{1, 1, 1} * intensity}};
  }
}

void frame_bounding_box(Scene& scene) {
  scene.default_camera = true;
  scene.default_light = true;
  place_camera(scene);
  scene.ambient = {0.05f, 0.05f, 0.05f};
  scene.background = {0.0f, 0.0f, 0.0f};
}

}  // namespace rayvec
