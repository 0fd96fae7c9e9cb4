// CameraRays: the pinhole camera's primary rays, through the look-at frame of rays/pinhole_camera.h
// (image right = cross(forward, up); image up is perpendicular to both); row 0 is the top row; fov_y
// spans the image height.
#pragma once
#include "rays/pinhole_camera.h"
#include "rays/ray.h"
#include "scene/scene.h"

namespace rayvec {

class CameraRays {
 public:
  explicit CameraRays(const Camera& camera);
  // The ray through continuous image position (px, py): px in [0, width) left to right,
  // py in [0, height) top to bottom; pixel (x, y)'s centre is (x + 0.5, y + 0.5). Unit direction.
  // Inline: built in the caller's array instead of returned through a temporary (whose scalar
  // stores, read back by a vector copy, stalled store forwarding once per primary ray).
  Ray ray(float px, float py) const {
    const float x = (px - half_w_) * scale_x_;
    const float y = (half_h_ - py) * scale_y_;
    return Ray{eye_, frame_.direction(x, y), 0.0f, kInf};
  }
  // The rays through (px[i], py[i]), i < n, into out[i]: ray(px[i], py[i]) bit for bit (the same
  // operations in the same order, four rays in SSE lanes), for a batch of primary rays.
  void rays(const float* px, const float* py, int n, Ray* out) const;
  Vec3f forward() const { return frame_.forward; }

 private:
  Vec3f eye_;
  PinholeFrame<float> frame_;
  float scale_x_, scale_y_;  // tan(fov_y/2)·aspect and tan(fov_y/2), over half the image size
  float half_w_, half_h_;
};

}  // namespace rayvec
