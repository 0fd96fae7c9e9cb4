// The coordinate range in which rayvec's float intersectors answer correctly (docs/formats.md,
// "Coordinate range"). Möller–Trumbore's t·det = (v0 − o)·(e2 × e1) grows as |x|³, the watertight
// test's T = U·Az + V·Bz + W·Cz as |x|³/|d| (Az = (v0z − oz)/dz); in float these overflow to Inf
// (a silent miss) from |x| ≈ 1e12 with unit directions. The loaders refuse input outside the range,
// which keeps every product below 2.4e38 (float's largest value is 3.4e38): vertices and ray
// origins within ±kMaxCoordinate, and a direction's largest component between kMinDirection and
// kMaxDirection in magnitude (its other components may be anything smaller, 0 included).
#pragma once
#include "math/vec3.h"

namespace rayvec {

inline constexpr float kMaxCoordinate = 1e10f;
inline constexpr float kMinDirection = 1e-6f;
inline constexpr float kMaxDirection = 1e16f;

// Ends the loaders' messages: "… is beyond " + kCoordinateRangeText.
inline constexpr const char* kCoordinateRangeText =
    "±1e10, the range in which rayvec's float intersectors answer correctly (scale the input down; "
    "see docs/formats.md, Coordinate range)";

// False for NaN too.
inline bool coordinate_in_range(float x) { return x >= -kMaxCoordinate && x <= kMaxCoordinate; }
inline bool point_in_range(Vec3f p) {
  return coordinate_in_range(p.x) && coordinate_in_range(p.y) && coordinate_in_range(p.z);
}

// The largest |component| of d.
inline float largest_component(Vec3f d) {
  const float ax = d.x < 0 ? -d.x : d.x, ay = d.y < 0 ? -d.y : d.y, az = d.z < 0 ? -d.z : d.z;
  return ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
}

}  // namespace rayvec
