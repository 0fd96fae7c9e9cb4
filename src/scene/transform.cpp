#include "scene/transform.h"

#include <cmath>
#include <numbers>

namespace rayvec {
namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

Mat3 rotation(int axis, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane rotated: y-z, z-x or x-y
  Mat3 r{};
  r[axis][axis] = 1;
  r[i][i] = c; r[i][j] = -s;
  r[j][i] = s; r[j][j] = c;
  return r;
}

Mat3 diagonal(double x, double y, double z) {
  Mat3 r{};
  r[0][0] = x; r[1][1] = y; r[2][2] = z;
  return r;
}

Vec3d apply(const Mat3& m, Vec3d v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
          m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

}  // namespace

AffineMap::AffineMap(const Transform& t) : translate_(Vec3d(t.translate)) {
  const Mat3 r = multiply(rotation(2, t.rotate_deg.z),
                          multiply(rotation(1, t.rotate_deg.y), rotation(0, t.rotate_deg.x)));
  linear_ = multiply(r, diagonal(t.scale.x, t.scale.y, t.scale.z));
  // (R·S)⁻ᵀ = R·S⁻¹ because R is orthonormal; scales are checked non-zero by the loader.
  normal_ = multiply(r, diagonal(1.0 / t.scale.x, 1.0 / t.scale.y, 1.0 / t.scale.z));
  flips_ = ((t.scale.x < 0) != (t.scale.y < 0)) != (t.scale.z < 0);  // odd number of mirrors
}

Vec3f AffineMap::point(Vec3f p) const {
  return Vec3f(apply(linear_, Vec3d(p)) + translate_);
}

Vec3f AffineMap::normal(Vec3f n) const {
  const Vec3d m = apply(normal_, Vec3d(n));
  const double len = length(m);
  return len > 0 ? Vec3f(m * (1.0 / len)) : n;
}

}  // namespace rayvec
