// Smoothing groups (`s N`) from an OBJ: read per triangle the same on both readers, and turned into
// shading normals by the scene where the file gives none.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "scene/transform.h"
#include "test_support.h"

namespace rayvec {
namespace {

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n";

ObjModel load_text(const std::string& name, const std::string& obj, bool reference, bool* fast = nullptr) {
  const std::string path = test::temp_dir("obj_smoothing") + "/" + name + ".obj";
  test::write_file(path, obj);
  ObjLoadTimes times;
  ObjModel m = load_obj(path, {.reference = reference}, &times);
  if (fast) *fast = times.fast;
  return m;
}

TEST(ObjSmoothing, EachTriangleHasItsFacesGroup) {
  // `s` holds across `g` and `o`; `s` alone changes nothing; `off` and 0 end a group
  const std::string obj = kSquare +
                          "f 1 2 3\n"                 // 0: before any s
                          "s 1\nf 1 2 3 4\n"          // 1, 2: a quad's two triangles
                          "g part\no obj\nf 1 2 5\n"  // 3
                          "s\nf 1 2 3\n"              // 4
                          "s off\nf 1 2 3\n"          // 5
                          "s 42\nf 1 2 3 4 5\n"       // 6, 7, 8: a pentagon's three
                          "s 0\nf 1 2 3\n";           // 9
  const std::vector<uint32_t> want{0, 1, 1, 1, 1, 0, 42, 42, 42, 0};
  for (const bool reference : {false, true}) {
    bool fast = false;
    const ObjModel m = load_text("groups", obj, reference, &fast);
    EXPECT_EQ(fast, !reference);
    EXPECT_EQ(m.triangle_smoothing, want) << (reference ? "tinyobjloader's path" : "fast reader");
  }
}

TEST(ObjSmoothing, NoGroupLeavesTheArrayEmpty) {
  for (const bool reference : {false, true}) {
    EXPECT_TRUE(load_text("none", kSquare + "f 1 2 3\n", reference).triangle_smoothing.empty());
    EXPECT_TRUE(load_text("off", kSquare + "s off\nf 1 2 3\ns 0\nf 1 2 3\ns 3\n", reference)
                    .triangle_smoothing.empty())
        << "a group that no face follows";
  }
}

TEST(ObjSmoothing, GroupNumbersTinyobjloaderReadsByAtoiTakeItsPath) {
  // tinyobjloader reads `s 2.5` as 2 and `s -1`, `s on` as 0; the fast reader leaves such lines to it
  for (const auto& [line, group] : std::vector<std::pair<std::string, uint32_t>>{
           {"s 2.5", 2}, {"s -1", 0}, {"s on", 0}, {"s 1234567890", 1234567890}}) {
    bool fast = true;
    const ObjModel m = load_text("atoi", kSquare + line + "\nf 1 2 3\n", false, &fast);
    EXPECT_FALSE(fast) << line;
    EXPECT_EQ(m.triangle_smoothing, (group == 0 ? std::vector<uint32_t>{} : std::vector<uint32_t>{group}))
        << line;
  }
}

// A cone's side as a fan of 8 triangles around its apex (vertex 1), optionally with normals for the
// first triangle, in group `s`.
std::string cone(const std::string& s, bool first_has_normals) {
  std::string obj = "v 0 0 1\n";
  for (int j = 0; j < 8; ++j) {
    const double a = 2 * 3.14159265358979 * j / 8;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  obj += "vn 1 0 0\n" + s + "\n";
  for (int j = 0; j < 8; ++j) {
    const std::string b = std::to_string(2 + j), c = std::to_string(2 + (j + 1) % 8);
    obj += j == 0 && first_has_normals ? "f 1//1 " + b + "//1 " + c + "//1\n" : "f 1 " + b + " " + c + "\n";
  }
  return obj;
}

TEST(ObjSmoothing, TheSceneShadesAGroupWithoutNormalsSmoothly) {
  Scene scene;
  scene.add_object(load_text("cone", cone("s 1", true), false), Transform{});
  ASSERT_EQ(scene.mesh.size(), 8u);
  const auto file = scene.normals(0);
  ASSERT_TRUE(file.has_value()) << "a face with normals keeps them";
  EXPECT_EQ((*file)[0], (Vec3f{1, 0, 0}));
  for (std::size_t t = 1; t < 8; ++t) {
    const auto n = scene.normals(t);
    ASSERT_TRUE(n.has_value()) << "triangle " << t;
    EXPECT_NEAR((*n)[0].z, 1.0f, 1e-6f) << "the apex: the mean of the whole fan, straight up";
    const Vec3f rim = scene.mesh.vertex(t, 1);  // on the rim, shared by two triangles
    const Vec3f geometric = normalize(cross(scene.mesh.vertex(t, 1) - scene.mesh.vertex(t, 0),
                                            scene.mesh.vertex(t, 2) - scene.mesh.vertex(t, 0)));
    EXPECT_GT(dot((*n)[1], Vec3f{rim.x, rim.y, 0}), dot(geometric, Vec3f{rim.x, rim.y, 0}) - 1e-6f)
        << "at the rim it leans outwards, between its two faces";
    EXPECT_GT(dot((*n)[1], geometric), 0.95f);
  }
  Scene flat;
  flat.add_object(load_text("flat_cone", cone("s off", false), false), Transform{});
  for (std::size_t t = 0; t < 8; ++t) EXPECT_FALSE(flat.normals(t).has_value()) << "s off: flat";
}

TEST(ObjSmoothing, AMirroredObjectsNormalsFollowItsTriangles) {
  const ObjModel model = load_text("mirrored", cone("s 5", false), false);
  Transform t;
  t.scale = {1, 1, -1};  // the apex below the rim
  Scene scene;
  scene.add_object(model, t);
  for (std::size_t i = 0; i < 8; ++i) {
    const auto n = scene.normals(i);
    ASSERT_TRUE(n.has_value());
    const Vec3f geometric = cross(scene.mesh.vertex(i, 1) - scene.mesh.vertex(i, 0),
                                  scene.mesh.vertex(i, 2) - scene.mesh.vertex(i, 0));
    for (int k = 0; k < 3; ++k) EXPECT_GT(dot((*n)[k], geometric), 0) << "triangle " << i << " corner " << k;
    EXPECT_NEAR((*n)[0].z, -1.0f, 1e-6f) << "the apex points down";
  }
}

}  // namespace
}  // namespace rayvec
