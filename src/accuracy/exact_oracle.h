// ExactOracle: the true answer to a ray–triangle query, computed with exact rational arithmetic
// (GMP), so tests and `rayvec accuracy` can judge the float intersectors against something that is
// not itself floating point. Every float is an exact rational, so for the given float inputs the
// oracle's answer is the truth. Slow (a double-precision filter with a generous error bound skips
// clear misses; everything else is exact): for tests and the accuracy command only.
//
// What counts as a hit (the same definition as the intersectors' contracts): the ray's line meets
// the triangle's plane in exactly one point (det ≠ 0: the triangle has nonzero area and the ray is
// not parallel to its plane), that point lies in the CLOSED triangle (edges and vertices included),
// and its parameter t satisfies tmin <= t <= tmax. A NaN or Inf anywhere in the ray or the triangle
// never hits. Coplanar rays and degenerate triangles therefore never hit, by definition.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "math/vec3.h"
#include "rays/ray.h"

namespace rayvec {

struct TriangleMesh;

// The exact nearest hit of one ray.
struct ExactHit {
  int32_t tri = -1;              // nearest triangle (lowest id among equal t); -1: miss
  double t = kInf;               // the exact t, rounded to double (toward zero)
  std::vector<int32_t> nearest;  // every triangle hit at exactly the nearest t, ascending ids

  bool hit() const { return tri >= 0; }
  bool is_nearest(int32_t id) const;  // id is one of `nearest`
};

// The exact predicate for one triangle; on a hit stores the exact t rounded to double in *t.
bool exact_hits_triangle(const Ray& ray, Vec3f v0, Vec3f v1, Vec3f v2, double* t = nullptr);

class ExactOracle {
 public:
  explicit ExactOracle(const TriangleMesh& mesh);
  ~ExactOracle();
  ExactOracle(ExactOracle&&) noexcept;
  ExactOracle& operator=(ExactOracle&&) noexcept;

  // The exact nearest hit among all triangles (ties: lowest id first in `nearest`). Thread-safe.
  ExactHit closest(const Ray& ray) const;
  // The exact predicate for triangle `tri` of the mesh.
  bool hits(const Ray& ray, int32_t tri) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rayvec
