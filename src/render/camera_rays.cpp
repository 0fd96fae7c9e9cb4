#include "render/camera_rays.h"

#include <cmath>
#include <numbers>

namespace rayvec {

CameraRays::CameraRays(const Camera& c) : eye_(c.eye), frame_(look_at_frame(c.eye, c.look_at, c.up)) {
  const float tan_half = std::tan(0.5f * c.fov_y * std::numbers::pi_v<float> / 180.0f);
  half_w_ = 0.5f * float(c.width);
  half_h_ = 0.5f * float(c.height);
  scale_y_ = tan_half / half_h_;
  scale_x_ = tan_half / half_h_;  // square pixels: the same angle per pixel both ways
}

}  // namespace rayvec
