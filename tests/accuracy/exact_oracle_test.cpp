// The exact oracle on cases whose answer is known by hand (exactly representable geometry).
#include <gtest/gtest.h>

#include <cmath>

#include "accuracy/exact_oracle.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

const Vec3f A{0, 0, 1}, B{1, 0, 1}, C{0, 1, 1};

TEST(ExactOracle, EdgesAndVerticesAreClosed) {
  double t = 0;
  EXPECT_TRUE(exact_hits_triangle(Ray{{0, 0, 0}, {0, 0, 1}}, A, B, C, &t));  // vertex
  EXPECT_EQ(t, 1.0);
  EXPECT_TRUE(exact_hits_triangle(Ray{{0.5f, 0.5f, 0}, {0, 0, 1}}, A, B, C));    // hypotenuse
  EXPECT_TRUE(exact_hits_triangle(Ray{{0.25f, 0, 0}, {0, 0, 2}}, A, B, C, &t));  // edge
  EXPECT_EQ(t, 0.5);
}

TEST(ExactOracle, OneUlpOutsideMisses) {
  const float past = std::nextafter(0.5f, 1.0f);
  EXPECT_FALSE(exact_hits_triangle(Ray{{past, 0.5f, 0}, {0, 0, 1}}, A, B, C));
  EXPECT_FALSE(exact_hits_triangle(Ray{{-1e-30f, 0.25f, 0}, {0, 0, 1}}, A, B, C));
  EXPECT_TRUE(exact_hits_triangle(Ray{{1e-30f, 0.25f, 0}, {0, 0, 1}}, A, B, C));
}

TEST(ExactOracle, TWindowIsClosed) {
  EXPECT_TRUE(exact_hits_triangle(Ray{{0.1f, 0.1f, 0}, {0, 0, 1}, 1.0f, 1.0f}, A, B, C));
  EXPECT_FALSE(
      exact_hits_triangle(Ray{{0.1f, 0.1f, 0}, {0, 0, 1}, 0.0f, std::nextafter(1.0f, 0.0f)}, A, B, C));
  EXPECT_FALSE(exact_hits_triangle(Ray{{0.1f, 0.1f, 0}, {0, 0, -1}}, A, B, C));  // behind
}

TEST(ExactOracle, CoplanarDegenerateAndNonFiniteNeverHit) {
  EXPECT_FALSE(exact_hits_triangle(Ray{{-1, 0.1f, 1}, {1, 0, 0}}, A, B, C));  // in the plane
  EXPECT_FALSE(exact_hits_triangle(Ray{{0.5f, 0.5f, 0}, {0, 0, 1}}, A, {1, 1, 1}, {2, 2, 1}));
  EXPECT_FALSE(exact_hits_triangle(Ray{{0, 0, 0}, {0, 0, 1}}, A, A, B));
  const float nan = std::nanf("");
  EXPECT_FALSE(exact_hits_triangle(Ray{{0.1f, nan, 0}, {0, 0, 1}}, A, B, C));
  EXPECT_FALSE(exact_hits_triangle(Ray{{0.1f, 0.1f, 0}, {0, 0, kInf}}, A, B, C));
  EXPECT_FALSE(exact_hits_triangle(Ray{{0.1f, 0.1f, 0}, {0, 0, 1}}, A, {1, nan, 1}, C));
  EXPECT_FALSE(exact_hits_triangle(Ray{{0, 0, 0}, {0, 0, 0}}, A, B, C));
}

TEST(ExactOracle, NearestListsEveryTriangleAtTheExactMinimum) {
  TriangleMesh m;
  m.add_triangle({0, 0, 3}, {1, 0, 3}, {0, 1, 3});  // 0: farther
  m.add_triangle(A, B, C);                          // 1
  m.add_triangle(B, C, {1, 1, 1});                  // 2: shares the hypotenuse with 1
  const ExactOracle oracle(m);
  const ExactHit hit = oracle.closest(Ray{{0.5f, 0.5f, 0}, {0, 0, 1}});
  EXPECT_EQ(hit.tri, 1);
  EXPECT_EQ(hit.t, 1.0);
  EXPECT_EQ(hit.nearest, (std::vector<int32_t>{1, 2}));
  EXPECT_TRUE(oracle.hits(Ray{{0.5f, 0.5f, 0}, {0, 0, 1}}, 0));
  EXPECT_FALSE(oracle.closest(Ray{{5, 5, 0}, {0, 0, 1}}).hit());
}

}  // namespace
}  // namespace rayvec
