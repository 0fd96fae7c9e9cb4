// Hand-checked ray–triangle cases, run through every intersector on every ISA this CPU has.
#include <gtest/gtest.h>

#include <cmath>

#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"
#include "geometry/triangle_mesh.h"
#include "test_support.h"

namespace rayvec {
namespace {

struct Case {
  Isa isa;
  Intersector intersector;
};

class MollerTrumbore : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    if (!isa_supported(GetParam().isa))
      GTEST_SKIP() << "CPU lacks " << isa_name(GetParam().isa) << ": skipped";
  }
  Hit closest(const TriangleMesh& mesh, const Ray& ray) const {
    const TriangleSoA soa(mesh);
    const auto& k = triangle_kernels(GetParam().isa, GetParam().intersector);
    Hit hit;
    k.closest(soa.arrays(), 0, soa.size(), ray, hit);
    return hit;
  }
  bool occluded(const TriangleMesh& mesh, const Ray& ray) const {
    const TriangleSoA soa(mesh);
    return triangle_kernels(GetParam().isa, GetParam().intersector)
        .occluded(soa.arrays(), 0, soa.size(), ray, nullptr);
  }
  bool epsilon_free() const { return GetParam().intersector != Intersector::paper; }
};

TriangleMesh one(Vec3f a, Vec3f b, Vec3f c) {
  TriangleMesh m;
  m.add_triangle(a, b, c);
  return m;
}

TEST_P(MollerTrumbore, HitsHandCheckedTriangleAtQuarter) {
  const Ray ray{{0, 0, 0}, {0, 0, 2}};
  const Hit hit = closest(one({-0.5f, 0.5f, 0.5f}, {0.5f, 0, 0.5f}, {0.5f, -1, 0.5f}), ray);
  ASSERT_EQ(hit.tri, 0);
  EXPECT_FLOAT_EQ(hit.t, 0.25f);
  // p = v0 + u e1 + v e2 = (0, 0, 0.5): u + v = 0.5 and 0.5u + 1.5v = 0.5
  EXPECT_NEAR(hit.u, 0.25f, 1e-6f);
  EXPECT_NEAR(hit.v, 0.25f, 1e-6f);
}

TEST_P(MollerTrumbore, MissesHandCheckedTriangle) {
  const Ray ray{{0, 0, 0}, {0, 0, 2}};
  const Hit hit = closest(one({-0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, -0.2f, 0.5f}), ray);
  EXPECT_EQ(hit.tri, -1);
  EXPECT_TRUE(std::isinf(hit.t));
}

TEST_P(MollerTrumbore, BackFacesHit) {
  const Ray ray{{0, 0, 1}, {0, 0, -1}};
  const Hit hit = closest(one({-0.5f, 0.5f, 0.5f}, {0.5f, 0, 0.5f}, {0.5f, -1, 0.5f}), ray);
  ASSERT_EQ(hit.tri, 0);
  EXPECT_FLOAT_EQ(hit.t, 0.5f);
}

TEST_P(MollerTrumbore, RespectsTminAndTmax) {
  const TriangleMesh m = one({-1, -1, 1}, {1, -1, 1}, {0, 1, 1});
  EXPECT_EQ(closest(m, Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 0.99f}).tri, -1);
  EXPECT_EQ(closest(m, Ray{{0, 0, 0}, {0, 0, 1}, 1.01f, kInf}).tri, -1);
  EXPECT_EQ(closest(m, Ray{{0, 0, 0}, {0, 0, 1}, 0.5f, 1.0f}).tri, 0);  // closed interval
  EXPECT_EQ(closest(m, Ray{{0, 0, 0}, {0, 0, 1}, 1.0f, 2.0f}).tri, 0);
  EXPECT_FALSE(occluded(m, Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 0.99f}));
  EXPECT_TRUE(occluded(m, Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 1.5f}));
}

TEST_P(MollerTrumbore, ParallelRayMisses) {
  const TriangleMesh m = one({-1, -1, 1}, {1, -1, 1}, {0, 1, 1});
  EXPECT_EQ(closest(m, Ray{{0, 0, 1}, {1, 0, 0}}).tri, -1);
  EXPECT_EQ(closest(m, Ray{{0, 0, 0}, {1, 0, 0}}).tri, -1);
}

TEST_P(MollerTrumbore, DegenerateTriangleNeverHitsAndGivesNoNan) {
  TriangleMesh m;
  m.add_triangle({0, 0, 1}, {1, 1, 1}, {2, 2, 1});                    // collinear
  m.add_triangle({0, 0, 1}, {0, 0, 1}, {1, 0, 1});                    // repeated vertex
  m.add_triangle({0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}, {0.5f, 0.5f, 1});  // a point
  for (const Ray& r :
       {Ray{{1, 1, 0}, {0, 0, 1}}, Ray{{0.5f, 0, 0}, {0, 0, 1}}, Ray{{0.5f, 0.5f, 0}, {0, 0, 1}}}) {
    const Hit hit = closest(m, r);
    EXPECT_EQ(hit.tri, -1);
    EXPECT_FALSE(std::isnan(hit.t));
    EXPECT_FALSE(occluded(m, r));
  }
}

TEST_P(MollerTrumbore, TinyTriangleHitWithoutEpsilon) {
  const TriangleMesh m = one({-1e-4f, -1e-4f, 1}, {1e-4f, -1e-4f, 1}, {0, 1e-4f, 1});
  const Hit hit = closest(m, Ray{{0, 0, 0}, {0, 0, 1}});
  if (epsilon_free()) {
    ASSERT_EQ(hit.tri, 0);
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
  } else {
    EXPECT_EQ(hit.tri, -1) << "paper mode culls |det| < 1e-6 by contract";
  }
}

TEST_P(MollerTrumbore, NanRayNeverHits) {
  const TriangleMesh m = one({-1, -1, 1}, {1, -1, 1}, {0, 1, 1});
  const float nan = std::nanf("");
  for (const Ray& r : {Ray{{nan, 0, 0}, {0, 0, 1}}, Ray{{0, 0, 0}, {0, nan, 1}},
                       Ray{{0, 0, 0}, {0, 0, 1}, nan, kInf}, Ray{{0, 0, 0}, {0, 0, kInf}}}) {
    const Hit hit = closest(m, r);
    EXPECT_EQ(hit.tri, -1);
    EXPECT_FALSE(std::isnan(hit.t));
  }
}

TEST_P(MollerTrumbore, NearestWinsAndTiesGoToLowestId) {
  TriangleMesh m;
  for (int k = 0; k < 40; ++k) {  // 40 triangles over several SIMD steps; same t for k = 7 and 33
    const float z = (k == 7 || k == 33) ? 2.0f : 3.0f + float(k);
    m.add_triangle({-1, -1, z}, {1, -1, z}, {0, 1, z});
  }
  const Hit hit = closest(m, Ray{{0, 0, 0}, {0, 0, 1}});
  EXPECT_EQ(hit.tri, 7);
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
}

std::vector<Case> all_cases() {
  std::vector<Case> out;
  for (Isa isa : kAllIsas)
    for (Intersector i : kAllIntersectors) out.push_back({isa, i});
  return out;
}

INSTANTIATE_TEST_SUITE_P(AllIsas, MollerTrumbore, ::testing::ValuesIn(all_cases()), [](const auto& info) {
  return std::string(isa_name(info.param.isa)) + "_" + intersector_name(info.param.intersector);
});

}  // namespace
}  // namespace rayvec
