// Vec3: the small 3-vector used across rayvec (positions, directions, colours).
// Plain aggregate, no SIMD: the kernels use the lane types of src/simd/ instead.
#pragma once
#include <algorithm>
#include <cmath>

namespace rayvec {

template <typename T>
struct Vec3 {
  T x{}, y{}, z{};

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
  friend constexpr Vec3 operator*(Vec3 a, T s) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator*(T s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator/(Vec3 a, T s) { return {a.x / s, a.y / s, a.z / s}; }
  constexpr Vec3& operator+=(Vec3 b) { return *this = *this + b; }
  constexpr Vec3& operator-=(Vec3 b) { return *this = *this - b; }
  constexpr Vec3& operator*=(T s) { return *this = *this * s; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

  template <typename U>
  constexpr explicit operator Vec3<U>() const {
    return {U(x), U(y), U(z)};
  }
};

using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

template <typename T>
constexpr T dot(Vec3<T> a, Vec3<T> b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr Vec3<T> cross(Vec3<T> a, Vec3<T> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
T length(Vec3<T> a) {
  return std::sqrt(dot(a, a));
}
template <typename T>
Vec3<T> normalize(Vec3<T> a) {
  return a * (T(1) / length(a));
}
template <typename T>
constexpr Vec3<T> min(Vec3<T> a, Vec3<T> b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
template <typename T>
constexpr Vec3<T> max(Vec3<T> a, Vec3<T> b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
// The largest of x, y, z (a colour's weight in the integrator).
template <typename T>
constexpr T max_component(Vec3<T> a) {
  return std::max({a.x, a.y, a.z});
}
template <typename T>
bool is_finite(Vec3<T> a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace rayvec
