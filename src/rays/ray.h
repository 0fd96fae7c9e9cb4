// Ray, Hit and RayBatch: what every query in rayvec takes and returns.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "math/vec3.h"

namespace rayvec {

inline constexpr float kInf = std::numeric_limits<float>::infinity();

// A ray o + t·d, valid for tmin <= t <= tmax (closed interval). d need not be normalized; t is in
// units of |d|.
struct Ray {
  Vec3f org;
  Vec3f dir;
  float tmin = 0.0f;
  float tmax = kInf;
};

// The nearest hit of a ray: triangle id (the triangle's index in the mesh), distance t and the
// barycentrics (u, v) of the hit point v0 + u·(v1 − v0) + v·(v2 − v0). A miss is tri = −1, t = +inf.
struct Hit {
  float t = kInf;
  float u = 0.0f;
  float v = 0.0f;
  int32_t tri = -1;

  bool hit() const { return tri >= 0; }
  // The ordering used everywhere: nearer wins; at equal t the lower triangle id wins.
  bool closer_than(float other_t, int32_t other_tri) const {
    return t < other_t || (t == other_t && tri >= 0 && (other_tri < 0 || tri < other_tri));
  }
};

// Many rays as structure-of-arrays, as read from a rays CSV or made by a camera.
struct RayBatch {
  std::vector<float> ox, oy, oz, dx, dy, dz, tmin, tmax;

  std::size_t size() const { return ox.size(); }
  void reserve(std::size_t n);
  void push_back(const Ray& r);
  void append(const RayBatch& other);
  Ray operator[](std::size_t i) const {
    return Ray{{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}, tmin[i], tmax[i]};
  }
};

inline void RayBatch::reserve(std::size_t n) {
  for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz, &tmin, &tmax}) v->reserve(n);
}

inline void RayBatch::append(const RayBatch& other) {
  std::vector<float>* const mine[] = {&ox, &oy, &oz, &dx, &dy, &dz, &tmin, &tmax};
  const std::vector<float>* const theirs[] = {&other.ox, &other.oy, &other.oz,   &other.dx,
                                              &other.dy, &other.dz, &other.tmin, &other.tmax};
  for (int k = 0; k < 8; ++k) mine[k]->insert(mine[k]->end(), theirs[k]->begin(), theirs[k]->end());
}

inline void RayBatch::push_back(const Ray& r) {
  ox.push_back(r.org.x);
  oy.push_back(r.org.y);
  oz.push_back(r.org.z);
  dx.push_back(r.dir.x);
  dy.push_back(r.dir.y);
  dz.push_back(r.dir.z);
  tmin.push_back(r.tmin);
  tmax.push_back(r.tmax);
}

}  // namespace rayvec
