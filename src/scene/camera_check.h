// What makes a camera unusable, checked once for every way one is given (a scene's "camera", the
// `render --eye/--look-at/--up/--fov` options), so each says which value is wrong instead of
// rendering NaN rays: the renderer turns eye, look_at and up into a float look-at frame, whose
// lengths overflow or underflow outside the ranges below.
#pragma once
#include <optional>
#include <string>

#include "scene/scene.h"

namespace rayvec {

struct CameraProblem {
  enum class Field { eye, look_at, up, fov_y } field;
  std::string what;  // reads after the field's name: "is beyond ±1e10, …"
};

// The first problem of `c`, or none:
// - fov_y outside (0, 180) degrees;
// - eye or look_at beyond ±kMaxCoordinate (geometry/coordinate_range.h), as vertices and ray origins;
// - up's largest component outside [kMinDirection, kMaxDirection] in magnitude, as ray directions
//   (only its direction counts: any length in that range gives the same frame up to rounding);
// - look_at equal to eye (reported on look_at);
// - up parallel to the view direction: the sine of their angle at most 1e-6, in double, whatever
//   up's length;
// - any other input whose float frame (look_at_frame) is not finite: eye and look_at so close that
//   their distance underflows (reported on look_at).
std::optional<CameraProblem> camera_problem(const Camera& c);

}  // namespace rayvec
