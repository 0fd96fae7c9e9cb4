// GLM's one includer: the rotations, the scale matrices and their products, all in double. The
// rotations are gtx/euler_angles' (cos and sin placed in the matrix); glm::rotate would normalize the
// axis and form the diagonal 1 as c + (1 − c), which can round.
#include "scene/transform.h"

#include <algorithm>
#include <numbers>

#define GLM_ENABLE_EXPERIMENTAL  // GLM asks for it before any gtx/ extension
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/gtx/matrix_operation.hpp>

namespace rayvec {
namespace {

glm::dvec3 to_glm(Vec3d v) { return {v.x, v.y, v.z}; }
Vec3d from_glm(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

glm::dmat3 load(const std::array<double, 9>& m) { return glm::make_mat3(m.data()); }
void store(const glm::dmat3& m, std::array<double, 9>& out) {
  const double* p = glm::value_ptr(m);
  std::copy(p, p + 9, out.begin());
}

double radians(float degrees) { return double(degrees) * std::numbers::pi / 180.0; }

}  // namespace

AffineMap::AffineMap(const Transform& t) : translate_(Vec3d(t.translate)) {
  // Right-handed rotations about x, y and z (the upper 3×3 of GLM's 4×4 matrices), x applied first.
  const glm::dmat3 rx(glm::eulerAngleX(radians(t.rotate_deg.x)));
  const glm::dmat3 ry(glm::eulerAngleY(radians(t.rotate_deg.y)));
  const glm::dmat3 rz(glm::eulerAngleZ(radians(t.rotate_deg.z)));
  const glm::dmat3 r = rz * (ry * rx);
  const glm::dvec3 s(t.scale.x, t.scale.y, t.scale.z);
  store(r * glm::diagonal3x3(s), linear_);
  // (R·S)⁻ᵀ = R·S⁻¹ because R is orthonormal; scales are checked non-zero by the loader. Formed so
  // rather than by glm::inverseTranspose, which would round through cofactors and a determinant.
  store(r * glm::diagonal3x3(1.0 / s), normal_);
  flips_ = ((t.scale.x < 0) != (t.scale.y < 0)) != (t.scale.z < 0);  // odd number of mirrors
  identity_ = linear_ == std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1} && translate_ == Vec3d{0, 0, 0};
}

Vec3f AffineMap::point(Vec3f p) const {
  return Vec3f(from_glm(load(linear_) * to_glm(Vec3d(p)) + to_glm(translate_)));
}

Vec3f AffineMap::normal(Vec3f n) const {
  const glm::dvec3 m = load(normal_) * to_glm(Vec3d(n));
  const double len = glm::length(m);
  return len > 0 ? Vec3f(from_glm(m * (1.0 / len))) : n;
}

}  // namespace rayvec
