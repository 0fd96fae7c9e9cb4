// The camera and light of a scene that does not give its own: a bare OBJ, or a scene JSON without
// "camera" (and without "lights"). Also `render --view/--eye/--look-at/--up/--fov`, which move any
// scene's camera. docs/scenes.md ("A bare OBJ") shows the defaults.
#pragma once
#include <optional>
#include <string>

#include "geometry/bbox.h"
#include "scene/scene.h"

namespace rayvec {

// Named views, by where the eye stands relative to the model (+y up, +z front, +x right):
//   iso     the default: a 3/4 view from above (25° up), 35° right of the front (+z); another side's
//           3/4 view (back-right, back-left, front-left) when it shows clearly more of the model
//           (front faces count fully, back faces half): the open side of a room or a box, the
//           front of a single-sided plane, a tilted plane from where it is seen most squarely
//   front +z, back −z, right +x, left −x, top +y, bottom −y (looking straight at the box's centre)
enum class View { iso, front, back, left, right, top, bottom };

// Throws InputError naming the choices for an unknown name.
View parse_view(const std::string& name);
const char* view_name(View view);

// The unit direction from the box's centre toward the eye for `view`. For iso, a box that is flat
// along an axis (extent below a tenth of its largest) is seen more squarely: that axis's component
// is raised so the flat side is seen about 60° from edge-on, never along its edge. Named views are
// taken literally (a model in the YZ plane seen from the front is edge-on).
Vec3f view_direction(View view, const BBox& box, const TriangleMesh& mesh);

struct CameraOverrides {
  std::optional<View> view;
  std::optional<Vec3f> eye, look_at, up;
  std::optional<float> fov_y;  // degrees, in (0, 180)
  bool any() const { return view || eye || look_at || up || fov_y; }
};

// Places the camera: a scene with scene.default_camera (or any scene given a view) is framed from
// view_direction (iso unless `o.view`), looking at the bounding box's centre from the distance where
// the mesh's vertices fill the image with a 5 % margin (fit_points_distance), with the camera's width, height
// and fov_y as they are now; then o.eye / o.look_at / o.up / o.fov_y replace those parts (an eye without
// look_at looks at the box's centre when the camera was framed). The up vector is +y, or ∓z for views along
// the y axis. With scene.default_light, the lights become one point light at the eye: every surface the
// camera sees is lit (shading is two-sided: normals face the viewer), and its intensity π·r² (r: the eye's
// distance to the box, at least 5 % of its diagonal) makes the nearest Lambertian surface facing the camera
// read about Kd. Throws InputError for a fov outside (0, 180), an eye equal to look_at, or an up vector
// parallel to the view.
void place_camera(Scene& scene, const CameraOverrides& o = {});

}  // namespace rayvec
