#include "rays/pinhole_camera.h"

#include <algorithm>
#include <cmath>

namespace rayvec {

template <typename T>
PinholeFrame<T> look_at_frame(Vec3<T> eye, Vec3<T> target, Vec3<T> up_hint) {
  PinholeFrame<T> f;
  f.forward = normalize(target - eye);
  f.right = normalize(cross(f.forward, up_hint));
  f.up = cross(f.right, f.forward);
  return f;
}

template <typename T>
BoxFraming<T> frame_box(const BBox& box, Vec3<T> toward_eye, T half_angle, T margin) {
  const Vec3<T> lo(box.lo), hi(box.hi);
  BoxFraming<T> b;
  b.center = (lo + hi) * T(0.5);
  b.radius = std::max(T(0.5) * length(hi - lo), T(1e-30));
  // The sphere's rim is at angle asin(radius / distance) = asin(sin(half_angle) / margin) off axis.
  b.distance = margin * b.radius / std::sin(half_angle);
  b.eye = b.center + normalize(toward_eye) * b.distance;
  return b;
}

template <typename T>
T fit_points_distance(const Vec3f* points, std::size_t n, Vec3<T> center, const PinholeFrame<T>& frame,
                      Vec3<T> toward_eye, T tan_half_x, T tan_half_y, T margin, T clearance) {
  const T tx = tan_half_x / margin, ty = tan_half_y / margin;
  T d = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<T> rel = Vec3<T>(points[i]) - center;
    // The point at depth (d − z) in front of the eye projects to (x, y)/(d − z) on the image plane.
    const T x = std::abs(dot(rel, frame.right)), y = std::abs(dot(rel, frame.up)), z = dot(rel, toward_eye);
    d = std::max({d, z + x / tx, z + y / ty, z + clearance});
  }
  return d;
}

template <typename T>
T narrower_half_fov(T half_fov_y, T aspect) {
  return aspect < 1 ? std::atan(std::tan(half_fov_y) * aspect) : half_fov_y;
}

template struct PinholeFrame<float>;
template struct PinholeFrame<double>;
template PinholeFrame<float> look_at_frame(Vec3f, Vec3f, Vec3f);
template PinholeFrame<double> look_at_frame(Vec3d, Vec3d, Vec3d);
template BoxFraming<float> frame_box(const BBox&, Vec3f, float, float);
template BoxFraming<double> frame_box(const BBox&, Vec3d, double, double);
template float fit_points_distance(const Vec3f*, std::size_t, Vec3f, const PinholeFrame<float>&, Vec3f, float,
                                   float, float, float);
template double fit_points_distance(const Vec3f*, std::size_t, Vec3d, const PinholeFrame<double>&, Vec3d,
                                    double, double, double, double);
template float narrower_half_fov(float, float);
template double narrower_half_fov(double, double);

}  // namespace rayvec
