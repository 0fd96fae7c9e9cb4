#include "scene/camera_check.h"

#include <cmath>

#include "geometry/coordinate_range.h"
#include "rays/pinhole_camera.h"

namespace rayvec {
namespace {

bool finite(Vec3f v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

std::optional<CameraProblem> camera_problem(const Camera& c) {
  using Field = CameraProblem::Field;
  if (!(c.fov_y > 0 && c.fov_y < 180))
    return CameraProblem{Field::fov_y, "must be between 0 and 180 degrees"};
  const std::string beyond = std::string("is beyond ") + kCoordinateRangeText;
  if (!point_in_range(c.eye)) return CameraProblem{Field::eye, beyond};
  if (!point_in_range(c.look_at)) return CameraProblem{Field::look_at, beyond};
  const float up_size = largest_component(c.up);
  if (!(up_size >= kMinDirection && up_size <= kMaxDirection))
    return CameraProblem{Field::up,
                         "needs its largest component between 1e-6 and 1e16 in magnitude (its length does "
                         "not matter: 0,1,0 is up)"};
  const Vec3d forward = Vec3d(c.look_at) - Vec3d(c.eye), up(c.up);
  if (!(length(forward) > 0))
    return CameraProblem{Field::look_at, "the eye must differ from the point looked at"};
  if (!(length(cross(forward, up)) > 1e-6 * length(forward) * length(up)))
    return CameraProblem{Field::up, "must not be zero or parallel to the view direction (eye to look-at)"};
  const PinholeFrame<float> f = look_at_frame(c.eye, c.look_at, c.up);
  if (!finite(f.forward) || !finite(f.right) || !finite(f.up))
    return CameraProblem{Field::look_at,
                         "is too close to the eye for a float camera frame (move them apart)"};
  return std::nullopt;
}

}  // namespace rayvec
