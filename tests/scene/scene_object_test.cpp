// Scene::add_object: a model's shared vertices stay shared (each used vertex transformed and stored
// once, unused ones left out), mirrors swap two corners, and later objects index their own vertices
// and their own normals and texture coordinates.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "scene/transform.h"

namespace rayvec {
namespace {

// Two triangles sharing the edge 1–2, and a vertex (index 4) that no triangle uses.
ObjModel quad() {
  ObjModel m;
  m.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {50, 50, 50}};
  m.mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  m.triangle_material = {-1, -1};
  return m;
}

TEST(SceneObject, SharedVerticesAreStoredOnceAndUnusedOnesLeftOut) {
  Scene scene;
  const ObjModel model = quad();
  scene.add_object(model, Transform{});
  ASSERT_EQ(scene.mesh.size(), 2u);
  EXPECT_EQ(scene.mesh.positions.size(), 4u);
  for (std::size_t t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(scene.mesh.vertex(t, k), model.mesh.vertex(t, k));
  EXPECT_EQ(scene.mesh.triangles[0][1], scene.mesh.triangles[1][0]);  // the shared edge
  EXPECT_EQ(scene.mesh.triangles[0][2], scene.mesh.triangles[1][2]);
  const auto [lo, hi] = scene.bounds();
  EXPECT_EQ(hi, (Vec3f{1, 1, 0})) << "the unused vertex is not part of the scene";
  EXPECT_EQ(lo, (Vec3f{0, 0, 0}));
}

TEST(SceneObject, TransformedVerticesEqualPointOfEachCorner) {
  Transform t;
  t.scale = {2, 3, 0.5f};
  t.rotate_deg = {10, 20, 30};
  t.translate = {1, -2, 3};
  const AffineMap map(t);
  Scene scene;
  const ObjModel model = quad();
  scene.add_object(model, t);
  EXPECT_EQ(scene.mesh.positions.size(), 4u);
  for (std::size_t tri = 0; tri < 2; ++tri)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(scene.mesh.vertex(tri, k), map.point(model.mesh.vertex(tri, k)));
}

TEST(SceneObject, MirrorSwapsTwoCornersAndKeepsVerticesShared) {
  Transform t;
  t.scale = {-1, 1, 1};
  const AffineMap map(t);
  ASSERT_TRUE(map.flips_orientation());
  Scene scene;
  const ObjModel model = quad();
  scene.add_object(model, t);
  EXPECT_EQ(scene.mesh.positions.size(), 4u);
  for (std::size_t tri = 0; tri < 2; ++tri) {
    EXPECT_EQ(scene.mesh.vertex(tri, 0), map.point(model.mesh.vertex(tri, 0)));
    EXPECT_EQ(scene.mesh.vertex(tri, 1), map.point(model.mesh.vertex(tri, 2)));
    EXPECT_EQ(scene.mesh.vertex(tri, 2), map.point(model.mesh.vertex(tri, 1)));
  }
}

TEST(SceneObject, LaterObjectsIndexTheirOwnVertices) {
  Scene scene;
  const ObjModel model = quad();
  scene.add_object(model, Transform{});
  Transform moved;
  moved.translate = {10, 0, 0};
  scene.add_object(model, moved);
  ASSERT_EQ(scene.mesh.size(), 4u);
  EXPECT_EQ(scene.mesh.positions.size(), 8u);
  EXPECT_EQ(scene.mesh.vertex(2, 0), (Vec3f{10, 0, 0}));
  EXPECT_EQ(scene.mesh.vertex(3, 1), (Vec3f{11, 1, 0}));
  EXPECT_EQ(scene.triangle_object[1], 0);
  EXPECT_EQ(scene.triangle_object[2], 1);
}

// The identity's shortcut gives what AffineMap::point gives, −0 included (stored as +0).
TEST(SceneObject, IdentityStoresWhatPointGives) {
  ObjModel model = quad();
  model.mesh.positions[0] = {-0.0f, -0.0f, 0.0f};
  Scene scene;
  scene.add_object(model, Transform{});
  const Vec3f p = scene.mesh.vertex(0, 0), q = AffineMap(Transform{}).point(model.mesh.positions[0]);
  EXPECT_EQ(std::signbit(p.x), std::signbit(q.x));
  EXPECT_FALSE(std::signbit(p.x));
  EXPECT_FALSE(std::signbit(p.y));
}

TEST(SceneObject, CornerNormalsAreTheTransformedNormals) {
  ObjModel model = quad();
  model.normals = {{0, 0, 1}, {0, 0, 2}};
  model.triangle_normals = {{0, 1, 0}, {-1, -1, -1}};
  Transform t;
  t.rotate_deg = {0, 90, 0};
  t.scale = {-1, 1, 1};
  const AffineMap map(t);
  Scene scene;
  scene.add_object(model, t);
  ASSERT_TRUE(scene.normals(0).has_value());
  EXPECT_FALSE(scene.normals(1).has_value());
  const std::array<Vec3f, 3> n = *scene.normals(0);
  EXPECT_EQ(n[0], map.normal(model.normals[0]));
  EXPECT_EQ(n[1], map.normal(model.normals[0]));  // corners 1 and 2 swapped by the mirror
  EXPECT_EQ(n[2], map.normal(model.normals[1]));
}

TEST(SceneObject, CornerAttributesIndexEachObjectsOwnTables) {
  Scene scene;
  scene.add_object(quad(), Transform{});  // neither normals nor texture coordinates
  EXPECT_TRUE(scene.normal_corners.empty()) << "a mesh without normals pays nothing for them";
  EXPECT_TRUE(scene.uv_corners.empty());
  ObjModel model = quad();
  model.normals = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  model.triangle_normals = {{-1, -1, -1}, {2, 1, 0}};
  model.texcoords = {{0.25f, 0.5f}, {0.75f, 1.0f}};
  model.triangle_texcoords = {{1, 0, 1}};
  scene.add_object(model, Transform{});
  ASSERT_EQ(scene.mesh.size(), 4u);
  for (std::size_t t = 0; t < 3; ++t) EXPECT_FALSE(scene.normals(t).has_value()) << "triangle " << t;
  ASSERT_TRUE(scene.normals(3).has_value());
  EXPECT_EQ((*scene.normals(3))[0], (Vec3f{0, 0, 1}));
  EXPECT_EQ((*scene.normals(3))[1], (Vec3f{0, 1, 0}));
  EXPECT_EQ((*scene.normals(3))[2], (Vec3f{1, 0, 0}));
  EXPECT_FALSE(scene.uv(0).has_value());
  ASSERT_TRUE(scene.uv(2).has_value());
  EXPECT_EQ((*scene.uv(2))[0], (std::array<float, 2>{0.75f, 1.0f}));
  EXPECT_EQ((*scene.uv(2))[1], (std::array<float, 2>{0.25f, 0.5f}));
  EXPECT_FALSE(scene.uv(3).has_value()) << "past the triangles the OBJ gave coordinates";
  scene.set_uv(0, {{{1, 2}, {3, 4}, {5, 6}}});  // a scene built in code
  ASSERT_TRUE(scene.uv(0).has_value());
  EXPECT_EQ((*scene.uv(0))[2], (std::array<float, 2>{5, 6}));
  EXPECT_EQ((*scene.uv(2))[0], (std::array<float, 2>{0.75f, 1.0f})) << "the others keep theirs";
}

TEST(SceneObject, ASceneTextureOverrideDropsTheMtlPlacementOfTheOneItReplaces) {
  Material m;
  m.map_Kd = "/models/tiles.png";
  m.map_Kd_scale = {4, 4};
  m.map_Kd_offset = {0.5f, 0};
  MaterialOverride kd_only;
  kd_only.Kd = Vec3f{1, 0, 0};
  kd_only.apply(m);
  EXPECT_EQ(m.map_Kd_scale, (std::array<float, 2>{4, 4})) << "the MTL's texture stays where it was";
  MaterialOverride texture;
  texture.map_Kd = "/scene/wood.png";
  texture.apply(m);
  EXPECT_EQ(m.map_Kd, "/scene/wood.png");
  EXPECT_EQ(m.map_Kd_scale, (std::array<float, 2>{1, 1}));
  EXPECT_EQ(m.map_Kd_offset, (std::array<float, 2>{0, 0}));
}

}  // namespace
}  // namespace rayvec
