// smooth_normals: angle-weighted vertex normals per smoothing group — the weights make a normal
// independent of how faces are cut into triangles; groups meet at creases; triangles without
// area, folds, tiny and far-away triangles stay well defined.
#include "scene/smooth_normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rayvec {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

std::vector<uint32_t> all_of(std::size_t n) {
  std::vector<uint32_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<uint32_t>(i);
  return v;
}

void expect_near(Vec3f got, Vec3d want, double tolerance, const std::string& what) {
  EXPECT_NEAR(got.x, want.x, tolerance) << what;
  EXPECT_NEAR(got.y, want.y, tolerance) << what;
  EXPECT_NEAR(got.z, want.z, tolerance) << what;
}

// The unit cube, its vertex i at (i & 1, i >> 1 & 1, i >> 2 & 1), faces wound outwards, each cut
// into two triangles — along the diagonal through vertex 0's side on some faces, the other on the
// rest — so that at a corner one face gives one triangle and another face two.
Triangles cube() {
  return {{0, 2, 3}, {0, 3, 1},   // z = 0, cut 0–3
          {4, 5, 7}, {4, 7, 6},   // z = 1, cut 4–7
          {0, 1, 5}, {0, 5, 4},   // y = 0, cut 0–5
          {2, 6, 3}, {3, 6, 7},   // y = 1, cut 3–6
          {0, 4, 2}, {2, 4, 6},   // x = 0, cut 2–4
          {1, 3, 7}, {1, 7, 5}};  // x = 1, cut 1–7
}

std::vector<Vec3f> cube_positions(Vec3f offset = {0, 0, 0}, float size = 1) {
  std::vector<Vec3f> p;
  for (int i = 0; i < 8; ++i)
    p.push_back(offset + Vec3f{float(i & 1), float(i >> 1 & 1), float(i >> 2 & 1)} * size);
  return p;
}

// Every corner of the cube: the normal of the corner's three faces, (±1, ±1, ±1)/√3.
void expect_cube_corners(const std::vector<Vec3f>& p, const Vec3f& offset, float size, double tolerance) {
  const Triangles t = cube();
  const std::vector<uint32_t> group(t.size(), 1);
  const SmoothedNormals s = smooth_normals(p, t, group, all_of(t.size()));
  ASSERT_EQ(s.corners.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      ASSERT_NE(s.corners[i][k], kNoSmoothNormal);
      const Vec3f corner = (p[t[i][k]] - offset) * (1 / size);
      const Vec3d want =
          Vec3d{corner.x * 2 - 1.0, corner.y * 2 - 1.0, corner.z * 2 - 1.0} * (1 / std::sqrt(3.0));
      expect_near(s.normals[s.corners[i][k]], want, tolerance,
                  "triangle " + std::to_string(i) + " corner " + std::to_string(k));
    }
}

TEST(SmoothNormals, ACubeCornerIsTheMeanOfItsFacesHoweverTheyAreCut) {
  // weighted by count or by area, a corner touched by both triangles of one face and one triangle of
  // another would lean towards the first
  expect_cube_corners(cube_positions(), {0, 0, 0}, 1, 1e-6);
}

TEST(SmoothNormals, TinyAndFarAwayTrianglesAreAsAccurate) {
  expect_cube_corners(cube_positions({0, 0, 0}, 1e-30f), {0, 0, 0}, 1e-30f, 1e-6);
  // one unit on a side, 10^5 from the origin: positions exact in float
  expect_cube_corners(cube_positions({1e5f, -1e5f, 1e5f}), {1e5f, -1e5f, 1e5f}, 1, 1e-6);
}

TEST(SmoothNormals, AFinelyCutSphereGetsItsRadialNormals) {
  std::vector<Vec3f> p;
  Triangles t;
  constexpr int kRings = 24, kSegments = 48;
  for (int i = 1; i < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) {
      const double theta = std::numbers::pi * i / kRings, phi = 2 * std::numbers::pi * j / kSegments;
      p.push_back(
          Vec3f(Vec3d{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)}));
    }
  const auto at = [](int i, int j) { return static_cast<uint32_t>((i - 1) * kSegments + (j % kSegments)); };
  for (int i = 1; i + 1 < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) {
      t.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      t.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  const std::vector<uint32_t> group(t.size(), 7);
  const SmoothedNormals s = smooth_normals(p, t, group, all_of(t.size()));
  // inner rings only (the outermost have neighbours on one side): normals point outwards
  for (std::size_t i = 4 * kSegments; i + 4 * kSegments < t.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const Vec3f n = s.normals[s.corners[i][k]];
      const Vec3f radial = normalize(p[t[i][k]]);
      ASSERT_GT(dot(n, radial), 0.999f) << "triangle " << i << " corner " << k;
    }
}

// Two squares folded along the x axis at a right angle: the edge's vertices 0 and 1 are shared.
struct Fold {
  std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}};
  Triangles t{{0, 1, 3},
              {0, 3, 2},  // the z = 0 square, normal +z
              {0, 4, 5},
              {0, 5, 1}};  // the y = 0 square, normal +y
};

TEST(SmoothNormals, OneGroupRoundsAnEdgeAndTwoGroupsKeepACrease) {
  const Fold f;
  const SmoothedNormals one = smooth_normals(f.p, f.t, std::vector<uint32_t>{1, 1, 1, 1}, all_of(4));
  const Vec3d diagonal = Vec3d{0, 1, 1} * (1 / std::sqrt(2.0));
  expect_near(one.normals[one.corners[0][0]], diagonal, 1e-6, "edge vertex, one group");
  expect_near(one.normals[one.corners[0][2]], {0, 0, 1}, 1e-6, "vertex 3, off the edge");
  const SmoothedNormals two = smooth_normals(f.p, f.t, std::vector<uint32_t>{1, 1, 2, 2}, all_of(4));
  expect_near(two.normals[two.corners[0][0]], {0, 0, 1}, 1e-6, "edge vertex, group 1");
  expect_near(two.normals[two.corners[0][1]], {0, 0, 1}, 1e-6, "edge vertex 1, group 1");
  expect_near(two.normals[two.corners[2][0]], {0, 1, 0}, 1e-6, "edge vertex, group 2");
  expect_near(two.normals[two.corners[3][2]], {0, 1, 0}, 1e-6, "edge vertex 1, group 2");
}

TEST(SmoothNormals, TrianglesNotWantedStillShapeTheirNeighbours) {
  const Fold f;
  const std::vector<uint32_t> wanted{0};
  const SmoothedNormals s = smooth_normals(f.p, f.t, std::vector<uint32_t>{1, 1, 1, 1}, wanted);
  ASSERT_EQ(s.corners.size(), 1u);
  expect_near(s.normals[s.corners[0][0]], Vec3d{0, 1, 1} * (1 / std::sqrt(2.0)), 1e-6, "edge vertex");
}

TEST(SmoothNormals, GroupZeroStaysFlat) {
  const Fold f;
  const SmoothedNormals s = smooth_normals(f.p, f.t, std::vector<uint32_t>{0, 1, 1, 0}, all_of(4));
  EXPECT_EQ(s.corners[0][0], kNoSmoothNormal);
  EXPECT_EQ(s.corners[3][1], kNoSmoothNormal);
  // at vertex 3 only triangle 1; at vertex 0 triangles 1 and 2, across the fold
  expect_near(s.normals[s.corners[1][1]], {0, 0, 1}, 1e-6, "vertex 3: triangle 1 only");
  expect_near(s.normals[s.corners[1][0]], Vec3d{0, 1, 1} * (1 / std::sqrt(2.0)), 1e-6, "vertex 0");
}

TEST(SmoothNormals, TheNormalFollowsTheWinding) {
  const std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const SmoothedNormals up = smooth_normals(p, Triangles{{0, 1, 2}}, std::vector<uint32_t>{1}, all_of(1));
  const SmoothedNormals down = smooth_normals(p, Triangles{{0, 2, 1}}, std::vector<uint32_t>{1}, all_of(1));
  for (int k = 0; k < 3; ++k) {
    expect_near(up.normals[up.corners[0][k]], {0, 0, 1}, 0, "counter-clockwise");
    expect_near(down.normals[down.corners[0][k]], {0, 0, -1}, 0, "clockwise");
  }
}

TEST(SmoothNormals, ATriangleWithoutAreaAddsNothing) {
  // a sliver with all three corners on the fold's edge line (vertices 0, 1 and their midpoint)
  Fold f;
  f.p.push_back({0.5f, 0, 0});
  f.t.push_back({0, 6, 1});
  const std::vector<uint32_t> group(5, 1);
  const SmoothedNormals s = smooth_normals(f.p, f.t, group, all_of(5));
  const Vec3d diagonal = Vec3d{0, 1, 1} * (1 / std::sqrt(2.0));
  expect_near(s.normals[s.corners[0][0]], diagonal, 1e-6, "the sliver adds nothing at vertex 0");
  EXPECT_EQ(s.corners[4][1], kNoSmoothNormal) << "its midpoint has no triangle with area: flat";
  const SmoothedNormals nan_corner =
      smooth_normals(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {NAN, 1, 0}}, Triangles{{0, 1, 2}},
                     std::vector<uint32_t>{1}, all_of(1));
  EXPECT_EQ(nan_corner.corners[0][0], kNoSmoothNormal) << "a non-finite corner contributes nothing";
}

TEST(SmoothNormals, AFoldOntoItselfStaysFlat) {
  // the same triangle twice, once each way round: the normals cancel at every corner
  const std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const SmoothedNormals s =
      smooth_normals(p, Triangles{{0, 1, 2}, {0, 2, 1}}, std::vector<uint32_t>{3, 3}, all_of(2));
  for (const auto& c : s.corners) EXPECT_EQ(c[0], kNoSmoothNormal);
}

TEST(SmoothNormals, ManyGroupsAtOneVertexEachGetTheirOwn) {
  // a fan of 8 triangles around vertex 0, in a cone, each in its own group: 8 normals at vertex 0
  std::vector<Vec3f> p{{0, 0, 1}};
  Triangles t;
  for (int j = 0; j < 8; ++j) {
    const double a = 2 * std::numbers::pi * j / 8;
    p.push_back(Vec3f(Vec3d{std::cos(a), std::sin(a), 0}));
  }
  std::vector<uint32_t> group;
  for (uint32_t j = 0; j < 8; ++j) {
    t.push_back({0, 1 + j, 1 + (j + 1) % 8});
    group.push_back(100 + j);
  }
  const SmoothedNormals s = smooth_normals(p, t, group, all_of(8));
  for (std::size_t i = 0; i < 8; ++i) {
    const Vec3f face = normalize(cross(p[t[i][1]] - p[t[i][0]], p[t[i][2]] - p[t[i][0]]));
    for (int k = 0; k < 3; ++k)
      expect_near(s.normals[s.corners[i][k]], Vec3d(face), 1e-6, "triangle " + std::to_string(i));
  }
}

}  // namespace
}  // namespace rayvec
