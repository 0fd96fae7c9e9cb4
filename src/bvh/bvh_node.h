// BBox and BinaryNode: the binary tree the SAH builder produces before it is collapsed into the wide
// BVH that traversal reads (wide_bvh.h).
#pragma once
#include <cstdint>
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

// A node of the binary build tree. Inner nodes have count == 0 and children `first` and `first + 1`;
// leaves hold triangles [first, first + count) of the builder's triangle order.
struct BinaryNode {
  BBox box;
  uint32_t first = 0;
  uint32_t count = 0;
  bool leaf() const { return count != 0; }
};

}  // namespace rayvec
