// The pinhole camera's geometry, written once for its three users: the renderer's camera rays
// (render/camera_rays), the ray sets of `bench rays` and `accuracy` (bench/ray_sets), and the camera
// of a bare OBJ or a scene without one (place_camera in scene/default_view.cpp). One rule places the
// eye so a box is in view, one look-at frame turns image-plane positions into directions.
// Templates over the scalar, instantiated for float (render, scene) and double (bench), so that each
// caller keeps the precision its outputs are defined in; pure math, no GLM (the bench sits below it).
#pragma once
#include <cstddef>

#include "geometry/bbox.h"
#include "math/vec3.h"

namespace rayvec {

// An orthonormal look-at frame: forward = normalize(target − eye),
// right = normalize(cross(forward, up_hint)), up = cross(right, forward). Image right is `right`,
// image up is `up`, and the camera looks along `forward`. up_hint need not be unit nor perpendicular
// to forward, but must not be zero or parallel to it (then right and up are NaN).
template <typename T>
struct PinholeFrame {
  Vec3<T> forward, right, up;

  // The unit direction through (u, v) on the image plane at distance 1 along forward, u to the right
  // and v up: normalize(forward + right·u + up·v). A half field of view θ spans u or v in ±tan θ.
  Vec3<T> direction(T u, T v) const { return normalize(forward + right * u + up * v); }
};

template <typename T>
PinholeFrame<T> look_at_frame(Vec3<T> eye, Vec3<T> target, Vec3<T> up_hint);

// Where a pinhole camera stands to see a whole box: looking from `eye` at `center`.
template <typename T>
struct BoxFraming {
  Vec3<T> center;  // the box's centre, (lo + hi)/2
  T radius{};      // the bounding sphere's radius: half the box's diagonal, at least 1e-30
  T distance{};    // from center to eye: margin · radius / sin(half_angle)
  Vec3<T> eye;     // center + normalize(toward_eye) · distance
};

// Frames `box` (non-empty, finite) from the direction `toward_eye` (from the box's centre toward the
// eye, any length but not zero) for a view of half-angle `half_angle` (radians, in (0, π/2)), with
// `margin` ≥ 1 (1: the bounding sphere touches the view's edge). Guarantee: seen from eye, the box's
// bounding sphere (so the whole box) lies inside the cone of half-angle asin(sin(half_angle)/margin)
// ≤ half_angle about the axis eye → center, and the eye is outside the sphere; a camera at eye that
// looks at center sees the whole box when the narrower half of its field of view (narrower_half_fov)
// is at least half_angle. A box that is a single point is framed as a sphere of radius 1e-30, so the
// eye still differs from the centre. Computed in T from the box's float corners.
template <typename T>
BoxFraming<T> frame_box(const BBox& box, Vec3<T> toward_eye, T half_angle, T margin);

// The smallest distance d from `center` along `toward_eye` (unit) at which a pinhole camera looking
// back at center with frame `frame` (look_at_frame(center + toward_eye, center, up)) sees every one
// of the n points within tan_half_x / margin and tan_half_y / margin of its axis: the tight fit that
// makes a model fill the image (frame_box fits the bounding sphere, smaller on screen). The eye
// stays in front of every point by `clearance` (> 0) at least.
template <typename T>
T fit_points_distance(const Vec3f* points, std::size_t n, Vec3<T> center, const PinholeFrame<T>& frame,
                      Vec3<T> toward_eye, T tan_half_x, T tan_half_y, T margin, T clearance);

// The half-angle of the narrower side of an image whose vertical field of view is 2·half_fov_y and
// whose aspect is width/height: half_fov_y for landscape and square images (aspect ≥ 1), else the
// horizontal half-angle atan(tan(half_fov_y) · aspect).
template <typename T>
T narrower_half_fov(T half_fov_y, T aspect);

}  // namespace rayvec
