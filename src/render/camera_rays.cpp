#include "render/camera_rays.h"

#include <array>
#include <cmath>
#include <numbers>

#include "simd/float4_sse.h"

namespace rayvec {

CameraRays::CameraRays(const Camera& c) : eye_(c.eye), frame_(look_at_frame(c.eye, c.look_at, c.up)) {
  const float tan_half = std::tan(0.5f * c.fov_y * std::numbers::pi_v<float> / 180.0f);
  half_w_ = 0.5f * float(c.width);
  half_h_ = 0.5f * float(c.height);
  scale_y_ = tan_half / half_h_;
  scale_x_ = tan_half / half_h_;  // square pixels: the same angle per pixel both ways
}

void CameraRays::rays(const float* px, const float* py, int n, Ray* out) const {
  using sse::Float4;
  const auto splat = [](Vec3f v) {
    return std::array<Float4, 3>{Float4::broadcast(v.x), Float4::broadcast(v.y), Float4::broadcast(v.z)};
  };
  const auto [fx, fy, fz] = splat(frame_.forward);
  const auto [rx, ry, rz] = splat(frame_.right);
  const auto [ux, uy, uz] = splat(frame_.up);
  const Float4 half_w = Float4::broadcast(half_w_), half_h = Float4::broadcast(half_h_);
  const Float4 scale_x = Float4::broadcast(scale_x_), scale_y = Float4::broadcast(scale_y_);
  const Float4 one = Float4::broadcast(1.0f);
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    // ray()'s arithmetic: x and y on the image plane, forward + right·x + up·y, then normalize's
    // dot (left to right), square root, reciprocal and product.
    const Float4 x = (Float4::load(px + i) - half_w) * scale_x;
    const Float4 y = (half_h - Float4::load(py + i)) * scale_y;
    const Float4 dx = (fx + rx * x) + ux * y, dy = (fy + ry * x) + uy * y, dz = (fz + rz * x) + uz * y;
    const Float4 inv = one / vsqrt((dx * dx + dy * dy) + dz * dz);
    float lanes[3][4];
    (dx * inv).store(lanes[0]);
    (dy * inv).store(lanes[1]);
    (dz * inv).store(lanes[2]);
    for (int k = 0; k < 4; ++k) out[i + k] = Ray{eye_, {lanes[0][k], lanes[1][k], lanes[2][k]}, 0.0f, kInf};
  }
  for (; i < n; ++i) out[i] = ray(px[i], py[i]);
}

}  // namespace rayvec
