// BBox: an axis-aligned bounding box, as the BVH builder and the camera framing use it.
#pragma once
#include <limits>

#include "math/vec3.h"

namespace rayvec {

// An axis-aligned box. The default box is empty (lo = +inf, hi = -inf) so that growing it by any
// point gives that point's box, and a ray never enters it.
struct BBox {
  Vec3f lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
           std::numeric_limits<float>::infinity()};
  Vec3f hi{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
           -std::numeric_limits<float>::infinity()};

  // min/max written so a NaN coordinate is ignored (the comparison fails and the old bound stays).
  void grow(Vec3f p) {
    for (int a = 0; a < 3; ++a) {
      if (p[a] < lo[a]) lo[a] = p[a];
      if (p[a] > hi[a]) hi[a] = p[a];
    }
  }
  void grow(const BBox& b) {
    grow(b.lo);
    grow(b.hi);
  }
  bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
  Vec3f extent() const { return hi - lo; }
  Vec3f center() const { return (lo + hi) * 0.5f; }
  // Half the surface area (the SAH only needs ratios); 0 for an empty box.
  float half_area() const {
    if (empty()) return 0.0f;
    const Vec3f e = extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

}  // namespace rayvec
