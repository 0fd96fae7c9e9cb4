// Vertex visibility (the CUDA study's workload): hand-checked answers, and the property that a
// triangle never hides its own corners whatever the rounding.
#include <gtest/gtest.h>

#include <random>

#include "accel/visibility.h"
#include "io/visibility_csv.h"

namespace rayvec {
namespace {

const std::string kData = RAYVEC_TEST_DATA;

std::vector<Visibility> run(const std::vector<Vec3f>& verts,
                            const std::vector<std::array<uint32_t, 3>>& faces, Vec3f origin,
                            std::size_t* dropped = nullptr, Isa isa = Isa::scalar) {
  const VisibilityMesh scene = build_visibility_mesh(verts, faces);
  if (dropped) *dropped = scene.dropped;
  const auto accel = make_accelerator(AccelKind::brute, scene.mesh, TraceConfig{isa, Intersector::mt});
  return compute_visibility(*accel, scene.mesh, verts, origin);
}

TEST(Visibility, HandCheckedFilesGiveKnownAnswers) {
  const auto verts = read_verts_csv(kData + "/visibility/verts.csv");
  const auto faces = read_faces_csv(kData + "/visibility/meshes.csv", verts.size());
  std::size_t dropped = 0;
  const auto got = run(verts, faces, {0, 0, 0}, &dropped);
  using V = Visibility;
  // Rows 0-2: the blocking triangle's own corners; 3: behind it; 4: in front; 5: nan; 6: beside;
  // 7: duplicate position of row 0; 8, 9: behind it (and corners of a triangle of their own).
  const std::vector<V> expected = {V::visible,   V::visible, V::visible, V::blocked, V::visible,
                                   V::undefined, V::visible, V::visible, V::blocked, V::blocked};
  EXPECT_EQ(got, expected);
  EXPECT_EQ(dropped, 1u);  // the face using the nan row
}

TEST(Visibility, EveryIsaGivesTheSameAnswers) {
  const auto verts = read_verts_csv(kData + "/visibility/verts.csv");
  const auto faces = read_faces_csv(kData + "/visibility/meshes.csv", verts.size());
  const auto reference = run(verts, faces, {0, 0, 0});
  for (Isa isa : supported_isas()) EXPECT_EQ(run(verts, faces, {0, 0, 0}, nullptr, isa), reference);
}

TEST(Visibility, BvhAgreesWithBruteForceOnAConnectedMesh) {
  // A random height field (shared vertices, so the own-triangle filter matters) seen from above-side.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> h(0.0f, 0.3f);
  const int n = 24;
  std::vector<Vec3f> verts;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) verts.push_back({i / float(n - 1), j / float(n - 1), h(rng)});
  std::vector<std::array<uint32_t, 3>> faces;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
      faces.push_back({a, b, d});
      faces.push_back({a, d, c});
    }
  const VisibilityMesh scene = build_visibility_mesh(verts, faces);
  const Vec3f origin{-0.5f, 0.3f, 0.6f};
  const TraceConfig config{best_isa(), Intersector::mt};
  const auto brute = make_accelerator(AccelKind::brute, scene.mesh, config);
  const auto bvh = make_accelerator(AccelKind::bvh, scene.mesh, config);
  const auto a = compute_visibility(*brute, scene.mesh, verts, origin);
  const auto b = compute_visibility(*bvh, scene.mesh, verts, origin);
  EXPECT_EQ(a, b);
  std::size_t blocked = 0;
  for (Visibility v : a) blocked += v == Visibility::blocked;
  EXPECT_GT(blocked, 0u);  // the terrain hides part of itself, so the comparison means something
  EXPECT_LT(blocked, verts.size());
}

TEST(Visibility, SegmentIsOpenAtTheOriginAndTheVertex) {
  // A triangle through the origin and one at exactly the vertex's depth do not block.
  const std::vector<Vec3f> verts = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0},  // through the origin
                                    {-1, -1, 2}, {1, -1, 2}, {0, 1, 2},  // at the vertex's depth
                                    {0, 0, 2},   {0, 0, 0}};
  const auto got = run(verts, {{0, 1, 2}, {3, 4, 5}}, {0, 0, 0});
  EXPECT_EQ(got[6], Visibility::visible);
  EXPECT_EQ(got[7], Visibility::visible);  // the origin itself: an empty segment
}

TEST(Visibility, ATriangleNeverHidesItsOwnCorners) {
  // Random triangles seen from random origins: rounding puts the corner's t on either side of 1,
  // which the open segment alone would not always absorb; the own-triangle filter must.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-10.0f, 10.0f);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Vec3f> verts;
    for (int k = 0; k < 3; ++k) verts.push_back({coord(rng), coord(rng), coord(rng)});
    const Vec3f origin{coord(rng), coord(rng), coord(rng)};
    for (Visibility v : run(verts, {{0, 1, 2}}, origin))
      ASSERT_EQ(v, Visibility::visible) << "trial " << trial;
  }
}

}  // namespace
}  // namespace rayvec
