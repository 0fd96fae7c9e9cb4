// Transform: an object's placement in the scene, and the matrices it implies.
#pragma once
#include <array>

#include "math/vec3.h"

namespace rayvec {

// world_from_object = translate · Rz · Ry · Rx · scale: scale first, then rotate about x, y and z
// (degrees, right-handed), then translate.
struct Transform {
  Vec3f scale{1, 1, 1};
  Vec3f rotate_deg{0, 0, 0};
  Vec3f translate{0, 0, 0};
};

// A 3×3 linear part plus a translation, in double so that composing keeps float inputs exact-ish.
class AffineMap {
 public:
  explicit AffineMap(const Transform& t);
  Vec3f point(Vec3f p) const;
  // Normals transform by the inverse transpose (R·S⁻¹ here); the result is normalized.
  Vec3f normal(Vec3f n) const;
  // True when the map mirrors space (odd number of negative scales): triangle winding must flip
  // so geometric normals keep pointing outward.
  bool flips_orientation() const { return flips_; }
  // True for the identity map (point() then returns its argument unchanged).
  bool is_identity() const { return identity_; }

 private:
  // Column-major 3×3 matrices, glm::dmat3's layout (transform.cpp is GLM's one includer).
  std::array<double, 9> linear_{}, normal_{};
  Vec3d translate_;
  bool flips_ = false;
  bool identity_ = false;
};

}  // namespace rayvec
