// Where a secondary ray starts: the hit point pushed off its surface by a scale-free amount, after
// Wächter & Binder (2019), "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing
// Gems ch. 6. Instead of a fixed epsilon (which is too small for large scenes and too large for
// small ones) each coordinate moves along the geometric normal by a number of ulps proportional to
// the normal's component, so the offset scales with the coordinate's own magnitude. Near the origin,
// where ulps get arbitrarily small, a tiny absolute offset takes over.
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>

#include "math/vec3.h"

namespace rayvec {

// p: a hit point computed from barycentrics (not o + t·d, whose error grows with t);
// n: the unit geometric normal on the side the new ray leaves toward.
inline Vec3f offset_ray_origin(Vec3f p, Vec3f n) {
  constexpr float kOrigin = 1.0f / 32.0f;         // below this |coordinate| use the absolute offset
  constexpr float kFloatScale = 1.0f / 65536.0f;  // the absolute offset near the origin
  constexpr float kIntScale = 256.0f;             // ulps moved for a unit normal component
  Vec3f out;
  for (int i = 0; i < 3; ++i) {
    const auto ulps = static_cast<int32_t>(kIntScale * n[i]);
    // Moving the bit pattern moves away from zero for positive ints; flip for negative coordinates
    // so that a positive normal component always increases the coordinate. In unsigned arithmetic:
    // next to −0 the signed sum would overflow (that coordinate takes the absolute offset anyway).
    const auto bits = std::bit_cast<uint32_t>(p[i]);
    const float moved = std::bit_cast<float>(bits + uint32_t(p[i] < 0 ? -ulps : ulps));
    out[i] = std::fabs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : moved;
  }
  return out;
}

}  // namespace rayvec
