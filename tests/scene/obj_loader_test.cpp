// load_obj: triangle ids after triangulation, materials, attributes, and the errors tinyobjloader
// would not report (nan vertices, indices out of range) with their line numbers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "scene/obj_loader.h"
#include "test_support.h"

namespace rayvec {
namespace {

const std::string kData = RAYVEC_TEST_DATA;

// The InputError message of loading `obj_text` from a fresh file named bad.obj ("" when it loads).
std::string error_of(const std::string& obj_text, std::string* path_out = nullptr) {
  const std::string path = test::temp_dir("obj_error") + "/bad.obj";
  test::write_file(path, obj_text);
  if (path_out) *path_out = path;
  try {
    load_obj(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Loads `obj`, written to dir/m.obj, on both readers — the fast one and the reference path
// (tinyobjloader) — and runs `check` on each.
template <typename Check>
void on_both_readers(const std::string& dir, const std::string& obj, Check check) {
  test::write_file(dir + "/m.obj", obj);
  for (const bool reference : {false, true}) {
    SCOPED_TRACE(reference ? "tinyobjloader's path" : "fast reader");
    ObjLoadTimes times;
    const ObjModel m = load_obj(dir + "/m.obj", {.reference = reference}, &times);
    EXPECT_EQ(times.fast, !reference);
    check(m);
  }
}

double area(const TriangleMesh& m, std::size_t t) {
  const Vec3f a = m.vertex(t, 0), b = m.vertex(t, 1), c = m.vertex(t, 2);
  return 0.5 * length(cross(Vec3d(b - a), Vec3d(c - a)));
}

TEST(ObjLoader, QuadSplitsAlongItsShorterDiagonal) {
  const ObjModel m = load_obj(kData + "/obj/polygons.obj");
  ASSERT_EQ(m.mesh.size(), 6u);  // quad 2 + pentagon 3 + triangle 1
  // Quad 1..4: diagonal 2-4 (length^2 5) is shorter than 1-3 (10), so tinyobjloader makes
  // (1,2,4) and (2,3,4): 0-based (0,1,3) and (1,2,3).
  EXPECT_EQ(m.mesh.triangles[0], (std::array<uint32_t, 3>{0, 1, 3}));
  EXPECT_EQ(m.mesh.triangles[1], (std::array<uint32_t, 3>{1, 2, 3}));
  // The closing triangle keeps its corners and comes last.
  EXPECT_EQ(m.mesh.triangles[5], (std::array<uint32_t, 3>{9, 10, 11}));
}

TEST(ObjLoader, PentagonBecomesThreeTrianglesCoveringIt) {
  const ObjModel m = load_obj(kData + "/obj/polygons.obj");
  ASSERT_EQ(m.mesh.size(), 6u);
  // Ids 2..4: corners from the pentagon (rows 4..8), area equal to the pentagon's (shoelace: 7.5).
  double total = 0;
  for (std::size_t t = 2; t <= 4; ++t) {
    for (uint32_t corner : m.mesh.triangles[t]) {
      EXPECT_GE(corner, 4u);
      EXPECT_LE(corner, 8u);
    }
    EXPECT_GT(area(m.mesh, t), 0.0);
    total += area(m.mesh, t);
  }
  EXPECT_NEAR(total, 7.5, 1e-6);
}

// Twice the area vector of the polygon `corners` (rows of m's positions), by Newell's method.
Vec3d newell(const TriangleMesh& m, const std::vector<uint32_t>& corners) {
  Vec3d n{};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3d a(m.positions[corners[i]]), b(m.positions[corners[(i + 1) % corners.size()]]);
    n += cross(a, b);
  }
  return n;
}

TEST(ObjLoader, AConcavePolygonWithABridgedHoleKeepsItsHole) {
  // assimp's ring: 66 corners, the outer circle and the hole joined along a doubled edge.
  // tinyobjloader's own ear clipping made 44 triangles covering part of the hole; both readers now
  // give 64 triangles, all facing the polygon's side, whose areas add up to the ring's.
  const ObjModel m = load_obj(kData + "/malformed/assimp/concave_polygon.obj");
  ASSERT_EQ(m.mesh.size(), 64u);
  std::vector<uint32_t> corners;
  const std::string text = test::read_file(kData + "/malformed/assimp/concave_polygon.obj");
  const std::size_t f = text.find("\nf ");
  ASSERT_NE(f, std::string::npos);
  std::istringstream face(text.substr(f + 3, text.find('\n', f + 1) - f - 3));
  for (std::string token; face >> token;) corners.push_back(static_cast<uint32_t>(std::stoul(token) - 1));
  ASSERT_EQ(corners.size(), 66u);
  const Vec3d normal = newell(m.mesh, corners);
  double total = 0;
  for (std::size_t t = 0; t < m.mesh.size(); ++t) {
    const Vec3d a(m.mesh.vertex(t, 0)), b(m.mesh.vertex(t, 1)), c(m.mesh.vertex(t, 2));
    const Vec3d n = cross(b - a, c - a);
    EXPECT_GE(dot(n, normal), 0.0) << "triangle " << t << " faces away from the polygon";
    total += length(n);
  }
  EXPECT_NEAR(total, length(normal), 1e-4 * length(normal));
  // the ring's hole is open: its area is well below the outer circle's
  double outer = 0;
  for (const Vec3f& p : m.mesh.positions)
    outer = std::max(outer, double(length(p - m.mesh.positions[corners[0]])));
  EXPECT_LT(0.5 * length(normal), 0.5 * M_PI * outer * outer);
}

TEST(ObjLoader, PolygonsOfMoreThan255CornersKeepEveryCorner) {
  // tinyobjloader counts a face's corners in a byte; a 300-gon must still give 298 triangles
  std::string obj;
  for (int k = 0; k < 300; ++k)
    obj += "v " + std::to_string(std::cos(k * 2 * M_PI / 300)) + " " +
           std::to_string(std::sin(k * 2 * M_PI / 300)) + " 0\n";
  obj += "f 1 2 3\nf";
  for (int k = 1; k <= 300; ++k) obj += " " + std::to_string(k);
  obj += "\nf 1 2 3 4 5\n";
  const std::string path = test::temp_dir("obj_large_face") + "/large.obj";
  test::write_file(path, obj);
  const ObjModel m = load_obj(path);
  ASSERT_EQ(m.mesh.size(), 1u + 298u + 3u);
  double total = 0;
  for (std::size_t t = 1; t <= 298; ++t) total += area(m.mesh, t);
  EXPECT_NEAR(total, 150 * std::sin(2 * M_PI / 300), 1e-4);  // the regular 300-gon's area
  for (uint32_t corner : m.mesh.triangles.back()) EXPECT_LT(corner, 5u);
}

TEST(ObjLoader, ReadsMaterialsFromTheMtl) {
  const ObjModel m = load_obj(kData + "/obj/polygons.obj");
  ASSERT_EQ(m.materials.size(), 2u);
  const Material& red = m.materials[0];
  EXPECT_EQ(red.name, "red");
  EXPECT_EQ(red.Ka, (Vec3f{0.1f, 0, 0}));
  EXPECT_EQ(red.Kd, (Vec3f{0.8f, 0.1f, 0.1f}));
  EXPECT_EQ(red.Ks, (Vec3f{0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(red.Ke, (Vec3f{0, 0, 0.2f}));
  EXPECT_EQ(red.Tf, (Vec3f{0.9f, 0.8f, 0.7f}));
  EXPECT_EQ(red.Ns, 64.0f);
  EXPECT_EQ(red.Ni, 1.5f);
  EXPECT_EQ(red.d, 0.75f);
  EXPECT_EQ(red.illum, 3);
  EXPECT_EQ(red.map_Kd, "");
  // map_Kd is relative to the MTL's directory; this one is missing, so the material keeps Kd alone
  // and the warning names the absolute path looked for (ObjLoader.MissingTextureIsAWarning).
  EXPECT_EQ(m.materials[1].map_Kd, "");
  // Per triangle: quad red (0), pentagon and triangle textured (1).
  EXPECT_EQ(m.triangle_material, (std::vector<int32_t>{0, 0, 1, 1, 1, 1}));
}

TEST(ObjLoader, MtlLibrariesNamedOnAnotherSystemAreFound) {
  // `mtllib` names written on Windows — another case, `\` separators, another machine's absolute
  // path — on both readers (the fast one, and tinyobjloader's for a file with an `l` line)
  const std::string dir = test::temp_dir("obj_mtllib_case");
  std::filesystem::create_directories(dir + "/materials");
  test::write_file(dir + "/materials/red.mtl", "newmtl red\nKd 1 0 0\n");
  // beside the OBJ, for the absolute path (another Kd, to tell which file was read)
  test::write_file(dir + "/red.mtl", "newmtl red\nKd 0 0 1\n");
  const std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
  for (const auto& [mtllib, kd] : {std::pair<std::string, Vec3f>{"Materials/Red.MTL", {1, 0, 0}},
                                   {".\\materials\\red.mtl", {1, 0, 0}},
                                   {"C:\\Users\\me\\Materials\\RED.mtl", {0, 0, 1}}})
    on_both_readers(dir, "mtllib " + mtllib + "\n" + body, [&](const ObjModel& m) {
      SCOPED_TRACE(mtllib);
      ASSERT_EQ(m.materials.size(), 1u) << (m.warnings.empty() ? "" : m.warnings[0]);
      EXPECT_EQ(m.materials[0].Kd, kd);
      EXPECT_EQ(m.triangle_material, (std::vector<int32_t>{0}));
    });
}

TEST(ObjLoader, LinesAndPointsAreNotReadEvenWhereTinyobjloaderWouldRefuseThem) {
  // a CAD export's edges with a comment after them: tinyobjloader reads the comment as index 0
  const std::string dir = test::temp_dir("obj_lines");
  on_both_readers(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 # edge\np 0 x\nf 1 2 3\n", [&](const ObjModel& m) {
    EXPECT_EQ(m.mesh.triangles, (std::vector<std::array<uint32_t, 3>>{{0, 1, 2}}));
    EXPECT_TRUE(m.warnings.empty());
  });
}

TEST(ObjLoader, MtlLibraryNamesWithSpacesAreFound) {
  // `mtllib Low Poly Tree.mtl`: tinyobjloader splits the line at spaces, unless the whole line,
  // naming a file, reaches it with its spaces escaped. Both readers; a missing name before a found
  // one still warns.
  const std::string dir = test::temp_dir("obj_mtllib_spaces");
  test::write_file(dir + "/Low Poly Tree.mtl", "newmtl bark\nKd 0.5 0.25 0\n");
  test::write_file(dir + "/leaf.mtl", "newmtl leaf\nKd 0 1 0\n");
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl bark\nf 1 2 3\nusemtl leaf\nf 1 2 3\n";
  on_both_readers(dir, "mtllib Low Poly Tree.mtl\nmtllib gone.mtl leaf.mtl\n" + tri, [&](const ObjModel& m) {
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[0].name, "bark");
    EXPECT_EQ(m.materials[1].name, "leaf");
    EXPECT_EQ(m.triangle_material, (std::vector<int32_t>{0, 1}));
    EXPECT_EQ(m.warnings, (std::vector<std::string>{dir + "/m.obj: material file " + dir +
                                                    "/gone.mtl not found; using default materials"}));
  });
  // no joined name exists: each piece warns, as before
  test::write_file(dir + "/n.obj", "mtllib no such.mtl\n" + tri);
  const ObjModel n = load_obj(dir + "/n.obj");
  EXPECT_TRUE(n.materials.empty());
  ASSERT_GE(n.warnings.size(), 2u);
  EXPECT_EQ(n.warnings[0], dir + "/n.obj: material file " + dir + "/no not found; using default materials");
  EXPECT_EQ(n.warnings[1],
            dir + "/n.obj: material file " + dir + "/such.mtl not found; using default materials");
}

TEST(ObjLoader, MaterialNamesWithSpacesAreTheirWholeName) {
  // 3ds Max names materials `Material #25`, `Material #26`: tinyobjloader read both usemtl lines
  // as "Material" and gave every triangle the first. Both readers; a name with a trailing blank.
  const std::string dir = test::temp_dir("obj_usemtl_spaces");
  test::write_file(dir + "/m.mtl",
                   "newmtl Material #25\nKd 1 0 0\nnewmtl Material #26\nKd 0 1 0\nnewmtl plain\n");
  const std::string obj =
      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Material #26\nf 1 2 3\n"
      "usemtl  Material #25 \r\nf 1 2 3\nusemtl plain\nf 1 2 3\nusemtl Material\nf 1 2 3\n";
  on_both_readers(dir, obj, [&](const ObjModel& m) {
    ASSERT_EQ(m.materials.size(), 3u);
    EXPECT_EQ(m.triangle_material, (std::vector<int32_t>{1, 0, 2, -1}));
    EXPECT_EQ(m.warnings,
              (std::vector<std::string>{dir + "/m.obj:11: usemtl 'Material': no MTL file loaded before it "
                                              "(mtllib) defines that material; drawn with the default "
                                              "material"}));
  });
}

TEST(ObjLoader, AMissingMaterialIsOneWarningWithItsCount) {
  // fifty `usemtl` lines naming a material no MTL file defines: one warning, on both readers
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 50; ++i) obj += "usemtl missing\nf 1 2 3\n";
  obj += "usemtl other\nf 1 2 3\n";
  const std::string dir = test::temp_dir("obj_missing_material");
  on_both_readers(dir, obj, [&](const ObjModel& m) {
    EXPECT_EQ(
        m.warnings,
        (std::vector<std::string>{
            dir + "/m.obj:4: usemtl 'missing': no MTL file loaded before it (mtllib) defines that material; "
                  "drawn with the default material (and on 49 later lines)",
            dir + "/m.obj:104: usemtl 'other': no MTL file loaded before it (mtllib) defines that material; "
                  "drawn with the default material"}));
    EXPECT_EQ(m.triangle_material, std::vector<int32_t>(51, -1));
  });
}

TEST(ObjLoader, AUsemtlBeforeItsMtllibIsNamedByItsLine) {
  // the first `usemtl a` comes before the MTL that defines a: only that line warns, on both readers
  const std::string dir = test::temp_dir("obj_usemtl_early");
  test::write_file(dir + "/m.mtl", "newmtl a\nKd 1 0 0\n");
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nmtllib m.mtl\nusemtl a\nf 1 2 3\n"
      "g\nusemtl b\nf 1 2 3\nusemtl a\nf 1 2 3\n";
  on_both_readers(dir, obj, [&](const ObjModel& m) {
    EXPECT_EQ(m.triangle_material, (std::vector<int32_t>{-1, 0, -1, 0}));
    const std::string tail =
        "': no MTL file loaded before it (mtllib) defines that material; drawn with the default material";
    EXPECT_EQ(m.warnings, (std::vector<std::string>{dir + "/m.obj:4: usemtl 'a" + tail,
                                                    dir + "/m.obj:10: usemtl 'b" + tail}));
  });
}

TEST(ObjLoader, MissingTextureIsAWarning) {
  const ObjModel m = load_obj(kData + "/obj/polygons.obj");
  bool found = false;
  const std::string looked_for =
      std::filesystem::absolute(kData + "/obj/mtl/tex/missing_wood.png").lexically_normal().string();
  for (const std::string& w : m.warnings)
    found |= w.find("(" + looked_for + ") not found") != std::string::npos;
  EXPECT_TRUE(found);
}

TEST(ObjLoader, KeepsPerCornerNormalsAndTexcoords) {
  const ObjModel m = load_obj(kData + "/obj/polygons.obj");
  ASSERT_EQ(m.normals.size(), 1u);
  ASSERT_EQ(m.texcoords.size(), 1u);
  EXPECT_EQ(m.texcoords[0][1], 0.25f);
  EXPECT_EQ(m.triangle_normals[0], (std::array<int32_t, 3>{0, 0, 0}));
  EXPECT_EQ(m.triangle_texcoords[0], (std::array<int32_t, 3>{0, 0, 0}));
  EXPECT_EQ(m.triangle_normals[2], (std::array<int32_t, 3>{-1, -1, -1}));
  EXPECT_EQ(m.triangle_normals[5], (std::array<int32_t, 3>{0, 0, 0}));
  EXPECT_EQ(m.triangle_texcoords[5], (std::array<int32_t, 3>{-1, -1, -1}));
}

// A kind of corner index that no face gives leaves its array empty, on both readers; one that only
// later faces give fills the earlier triangles with -1.
TEST(ObjLoader, CornerIndexArraysAreEmptyWhenNoFaceGivesThatKind) {
  const std::string dir = test::temp_dir("obj_corner_kinds");
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  test::write_file(dir + "/plain.obj", quad + "vn 0 0 1\nvt 0 0\nf 1 2 3\nf 1 2 3 4\n");
  test::write_file(dir + "/late.obj", quad + "vn 0 0 1\nf 1 2 3\nf 1 2 3 4\nf 1//1 2//1 3//1\n");
  for (const bool reference : {false, true}) {
    ObjLoadOptions options;
    options.reference = reference;
    ObjLoadTimes times;
    const ObjModel plain = load_obj(dir + "/plain.obj", options, &times);
    EXPECT_EQ(times.fast, !reference);
    EXPECT_EQ(plain.mesh.size(), 3u);
    EXPECT_EQ(plain.normals.size(), 1u);
    EXPECT_TRUE(plain.triangle_normals.empty()) << "reference " << reference;
    EXPECT_TRUE(plain.triangle_texcoords.empty()) << "reference " << reference;
    const ObjModel late = load_obj(dir + "/late.obj", options);
    const std::array<int32_t, 3> none{-1, -1, -1}, first{0, 0, 0};
    EXPECT_EQ(late.triangle_normals, (std::vector<std::array<int32_t, 3>>{none, none, none, first}))
        << "reference " << reference;
    EXPECT_TRUE(late.triangle_texcoords.empty()) << "reference " << reference;
  }
}

TEST(ObjLoader, NonFiniteVertexIsRejectedWithItsLine) {
  std::string path;
  const std::string e = error_of("v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n", &path);
  EXPECT_NE(e.find(path + ":3: `v` coordinate 2 'nan' is not a finite number"), std::string::npos) << e;
  EXPECT_NE(error_of("# c\nv inf 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find(":2: `v` coordinate 1 'inf'"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 1e39\nv 0 1 0\nf 1 2 3\n").find(":2:"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n").find(":2: `v` needs 3 coordinates, found 2"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -nan\nf 1 2 3\n").find(":4: `vn`"),
            std::string::npos);
}

TEST(ObjLoader, FaceIndexOutOfRangeIsRejectedWithItsLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_NE(error_of(tri + "f 1 2 3\nf 1 2 9\n")
                .find(":5: face vertex index 9 is out of range: the file defines 3 vertices"),
            std::string::npos)
      << error_of(tri + "f 1 2 9\n");
  EXPECT_NE(error_of(tri + "f 1 2 3 7\n").find(":4: face vertex index 7 is out of range"), std::string::npos);
  EXPECT_NE(error_of(tri + "f -1 -2 -4\n").find(":4: face corner 3: vertex index '-4' is out of range"),
            std::string::npos);
  EXPECT_NE(error_of(tri + "f 0 1 2\n").find(":4: face corner 1: vertex index '0' is 0"), std::string::npos);
  EXPECT_NE(error_of(tri + "vn 0 0 1\nf 1//1 2//2 3//1\n").find(":5: face normal index 2 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of(tri + "f 1 2\n").find(":4: a face needs at least 3 corners, found 2"),
            std::string::npos);
  EXPECT_NE(error_of(tri + "f 1 2 x\n").find(":4: face corner 3: vertex index 'x' is not an integer"),
            std::string::npos);
  // Relative indices and a vertex defined after its face are valid OBJ.
  EXPECT_EQ(error_of(tri + "f -3 -2 -1\nf 1 2 4\nv 1 1 0\n"), "");
}

TEST(ObjLoader, AcceptsCrlfLineEnds) {
  EXPECT_EQ(error_of("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"), "");
  EXPECT_NE(error_of("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 4\r\n").find(":4: face vertex index 4"),
            std::string::npos);
}

TEST(ObjLoader, MissingFileAndEmptyMeshAreInputErrors) {
  const std::string path = test::temp_dir("obj_missing") + "/none.obj";
  try {
    load_obj(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": cannot read"), std::string::npos) << e.what();
  }
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\n").find("no triangles"), std::string::npos);
}

TEST(ObjLoader, MissingMtlIsAWarningNotAnError) {
  const std::string dir = test::temp_dir("obj_nomtl");
  test::write_file(dir + "/m.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
  const ObjModel m = load_obj(dir + "/m.obj");
  ASSERT_EQ(m.mesh.size(), 1u);
  EXPECT_EQ(m.triangle_material[0], -1);
  bool found = false;
  for (const std::string& w : m.warnings) found |= w.find("gone.mtl") != std::string::npos;
  EXPECT_TRUE(found);
}

// A file of kObjTwoThreadsFrom bytes and more is parsed on two threads when the caller may use two,
// with the same result as on one; a smaller file, or a caller with one thread, uses one.
TEST(ObjLoader, BigFilesUseTwoThreadsWhenTheCallerHasThem) {
  const std::string dir = test::temp_dir("obj_two_threads");
  std::string big;
  big.reserve(kObjTwoThreadsFrom + 4096);
  int rows = 0;
  for (; big.size() < kObjTwoThreadsFrom; ++rows)
    for (int x = 0; x < 100; ++x)
      big += "v " + std::to_string(x) + ".125 " + std::to_string(rows) + ".5 0.0625\n";
  for (int r = 0; r + 1 < rows; ++r)
    for (int x = 0; x + 1 < 100; ++x) {
      const int a = r * 100 + x + 1, b = a + 1, c = a + 100;
      big += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    }
  test::write_file(dir + "/big.obj", big);
  test::write_file(dir + "/small.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");

  ObjLoadTimes two, one, small;
  const ObjModel a = load_obj(dir + "/big.obj", ObjLoadOptions{.available_threads = 2}, &two);
  const ObjModel b = load_obj(dir + "/big.obj", ObjLoadOptions{.available_threads = 1}, &one);
  load_obj(dir + "/small.obj", ObjLoadOptions{.available_threads = 8}, &small);
  EXPECT_TRUE(two.fast);
  EXPECT_EQ(two.threads, 2);
  EXPECT_EQ(one.threads, 1);
  EXPECT_EQ(small.threads, 1);
  ASSERT_EQ(a.mesh.size(), std::size_t(rows - 1) * 99);
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

}  // namespace
}  // namespace rayvec
