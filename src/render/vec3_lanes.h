// Vec3Lanes: a Vec3f per hit of a tile as three float arrays, and restrict views of them, so that
// a loop over the hits runs in SIMD lanes. The loops that shade a tile's hits together
// (render/tile_lighting.cpp, render/tile_waves.cpp) read and write distinct arrays: views with
// restrict pointers tell the compiler so, and g++ vectorizes plain loops over them (it left
// `#pragma omp simd` loops over small structs scalar).
#pragma once
#include <cstddef>
#include <vector>

#include "math/vec3.h"

namespace rayvec {

struct Vec3Lanes {
  std::vector<float> x, y, z;
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    z.resize(n);
  }
  Vec3f operator[](std::size_t j) const { return {x[j], y[j], z[j]}; }
  void set(std::size_t j, Vec3f v) {
    x[j] = v.x;
    y[j] = v.y;
    z[j] = v.z;
  }
};

// Read and write views of Vec3Lanes for the vectorized loops.
struct Lanes3In {
  const float* __restrict x;
  const float* __restrict y;
  const float* __restrict z;
  Vec3f operator[](int j) const { return {x[j], y[j], z[j]}; }
};
struct Lanes3Out {
  float* __restrict x;
  float* __restrict y;
  float* __restrict z;
  void set(int j, Vec3f v) const {
    x[j] = v.x;
    y[j] = v.y;
    z[j] = v.z;
  }
};
inline Lanes3In in(const Vec3Lanes& v) { return {v.x.data(), v.y.data(), v.z.data()}; }
inline Lanes3Out out(Vec3Lanes& v) { return {v.x.data(), v.y.data(), v.z.data()}; }

}  // namespace rayvec
