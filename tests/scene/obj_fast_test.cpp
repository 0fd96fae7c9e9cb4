// The fast OBJ reader against tinyobjloader (the reference): on every OBJ in tests/data and in
// Debian's assimp-testmodels, on hand-written edge cases and on random files, loading through the
// fast reader (1 to 4 pieces) and through tinyobjloader gives the same triangles in the same order,
// the same normal/texcoord indices, materials, warnings and errors (`file:line`); coordinates agree
// to one float step (tinyobjloader's decimal conversion is not correctly rounded).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "io/input_error.h"
#include "scene/obj_loader.h"
#include "test_support.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  ObjModel model;
  std::string error;  // InputError's message, "" when it loaded
  bool fast = false;
};

Outcome load(const std::string& path, const ObjLoadOptions& options) {
  Outcome out;
  ObjLoadTimes times;
  try {
    out.model = load_obj(path, options, &times);
    out.fast = times.fast;
  } catch (const InputError& e) {
    out.error = e.what();
  }
  return out;
}

bool within_one_step(float a, float b) {
  if (a == b) return true;
  const auto ia = std::bit_cast<int32_t>(a), ib = std::bit_cast<int32_t>(b);
  return (ia < 0) == (ib < 0) && std::abs(int64_t(ia) - int64_t(ib)) <= 1;
}

template <typename Points>
void expect_close(const Points& a, const Points& b, int dims, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < dims; ++k)
      ASSERT_TRUE(within_one_step(a[i][k], b[i][k]))
          << what << " " << i << "[" << k << "]: " << a[i][k] << " vs " << b[i][k];
}

// Every position's colour, white where the model has none (the reference path cannot tell a file
// without colours from one whose colours are all white).
std::vector<Vec3f> colors_of(const ObjModel& m) {
  return m.colors.empty() ? std::vector<Vec3f>(m.mesh.positions.size(), Vec3f{1, 1, 1}) : m.colors;
}

// Loads `path` through tinyobjloader and through the fast reader in 1..4 pieces; all must agree.
// Returns whether the fast reader took the file.
bool expect_same_as_reference(const std::string& path) {
  const Outcome ref = load(path, {.reference = true});
  EXPECT_FALSE(ref.fast) << path << ": the reference load took the fast reader";
  bool fast = false;
  for (int threads = 1; threads <= 4; ++threads) {
    const std::string what = path + " (" + std::to_string(threads) + " pieces)";
    const Outcome got = load(path, {.threads = threads});
    fast = fast || got.fast;
    EXPECT_EQ(got.error, ref.error) << what;
    const ObjModel &a = got.model, &b = ref.model;
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles) << what;
    EXPECT_EQ(a.triangle_normals, b.triangle_normals) << what;
    EXPECT_EQ(a.triangle_texcoords, b.triangle_texcoords) << what;
    EXPECT_EQ(a.triangle_material, b.triangle_material) << what;
    EXPECT_EQ(a.triangle_smoothing, b.triangle_smoothing) << what;
    EXPECT_EQ(a.warnings, b.warnings) << what;
    expect_close(a.mesh.positions, b.mesh.positions, 3, what + " position");
    expect_close(a.normals, b.normals, 3, what + " normal");
    expect_close(colors_of(a), colors_of(b), 3, what + " colour");
    expect_close(a.texcoords, b.texcoords, 2, what + " texcoord");
    EXPECT_EQ(a.materials.size(), b.materials.size()) << what;
    for (std::size_t i = 0; i < std::min(a.materials.size(), b.materials.size()); ++i) {
      EXPECT_EQ(a.materials[i].name, b.materials[i].name) << what;
      EXPECT_EQ(a.materials[i].map_Kd, b.materials[i].map_Kd) << what;
      EXPECT_EQ(a.materials[i].Kd, b.materials[i].Kd) << what;
    }
  }
  return fast;
}

std::vector<std::string> files_under(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() != ".mtl" && e.path().extension() != ".png" &&
        e.path().extension() != ".md" && e.path().extension() != ".txt")
      out.push_back(e.path().string());
  return out;
}

TEST(ObjFast, SameAsTinyobjloaderOnEveryObjInTestData) {
  int taken = 0, files = 0;
  for (const char* dir : {"/obj", "/malformed", "/fuzz", "/fuzz_corpus/obj"})
    for (const std::string& path : files_under(RAYVEC_TEST_DATA + std::string(dir))) {
      ++files;
      taken += expect_same_as_reference(path);
    }
  EXPECT_GE(files, 19);
  EXPECT_GE(taken, 5);  // the fast reader is not just handing everything back
}

TEST(ObjFast, SameAsTinyobjloaderOnAssimpTestModels) {
  const std::string dir = "/usr/share/assimp/models";
  if (!fs::is_directory(dir + "/OBJ")) GTEST_SKIP() << "needs Debian's assimp-testmodels (" << dir << ")";
  int files = 0, taken = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".obj") {
      ++files;
      taken += expect_same_as_reference(e.path().string());
    }
  EXPECT_EQ(files, 25);  // OBJ/ and invalid/ of assimp-testmodels 5.2.5
  EXPECT_GT(taken, 10);
}

// Each case in its own directory with m.mtl (materials a and b).
bool same_on(const std::string& name, const std::string& obj) {
  const std::string dir = test::temp_dir("obj_fast_" + name);
  test::write_file(dir + "/m.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
  test::write_file(dir + "/m.obj", obj);
  return expect_same_as_reference(dir + "/m.obj");
}

TEST(ObjFast, SameAsTinyobjloaderOnEdgeCases) {
  const std::string quad = "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 3 1\nv 0 3 1\n";
  // taken by the fast reader
  EXPECT_TRUE(same_on("quads", quad + "f 1 2 3 4\nf 5 6 7 8\nf 4 3 2 1\n"));
  // concave quads (arrowheads): split from the reflex corner, whichever corner that is
  EXPECT_TRUE(same_on("concave_quads",
                      "v 0 0 0\nv 10 -1 0\nv 5 0 0\nv 10 1 0\n"
                      "f 1 2 3 4\nf 2 3 4 1\nf 4 3 2 1\nf 3 4 1 2\n"));
  EXPECT_TRUE(same_on("relative", quad + "f -4 -3 -2\nv 9 9 9\nf -1 -2 -3 -4\nf 1 2 -1\n"));
  EXPECT_TRUE(same_on("attributes", quad + "vt 0.5\nvt .25 +.75 7\nvn 0 0 1\nvn -0 1e-3 1E2\n"
                                           "f 1/1 2/2 3/1\nf 1//1 2//2 3//-1\nf 1/-1/1 2/2/2 3/1/1 4/2/2\n"));
  EXPECT_TRUE(same_on("late_attributes", quad + "vn 0 0 1\nvt 0 0\nf 1 2 3 4\nf 5 6 7\n"
                                                "f 1//1 2//1 3//1\nf 1/1 2/1 3/1 4/1\nf 5 6 7 8\n"));
  EXPECT_TRUE(same_on("unused_attributes", quad + "vn 0 0 1\nvt 0 0\nf 1 2 3 4\nf 5 6 7\n"));
  EXPECT_TRUE(same_on("materials", quad + "usemtl a\nf 1 2 3\nmtllib m.mtl\nf 1 2 3\nusemtl b\nf 1 2 3\n"
                                          "usemtl nope\nf 1 2 3 4\nusemtl a\nusemtl a\nf 2 3 4\n"));
  EXPECT_TRUE(same_on("mtllibs", quad + "mtllib missing.mtl m.mtl\nmtllib m.mtl\nusemtlb\nf 1 2 3\n"));
  EXPECT_TRUE(same_on("missing_mtl", quad + "mtllib missing.mtl\nusemtl a\nf 1 2 3\n"));
  EXPECT_TRUE(same_on("groups", quad + "g\ng \no\no x\ns off\ns 1\nt x 1/0/0 5\ng a b\nf 1 2 3\n"));
  EXPECT_TRUE(same_on("blanks",
                      "# c\n\n  \t\nv 0 0 0 1 0 0\r\nv\t1 0 0\t\r\nv 0 1 0 # c\n f 1 2 3 \t\n"
                      "vp 1 2\nf 1 2 3"));
  EXPECT_TRUE(same_on("two_digit_exponents", quad + "vt 0 1.4e-45\nvn 0 0 -3.4E+38\nf 1/1/1 2/1/1 3/1/1\n"));
  // polygons: cut by the same triangulate_polygon on both paths, attributes following their corners
  EXPECT_TRUE(
      same_on("polygons", quad + "vt 0 0\nvt 1 0\nvn 0 0 1\nf 1 2 3 4 5\nf 1/1 2/2 3/1 7/2 8/1\n"
                                 "f -1//1 -2//1 -3//1 -4//1 -5//1 -6//1\nusemtl a\nf 8 7 6 5 4 3 2 1\n"));
  EXPECT_TRUE(same_on("keyhole",
                      "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 1 1 0\nv 1 3 0\nv 3 3 0\nv 3 1 0\n"
                      "f 1 2 3 4 1 5 6 7 8 5\n"));
  // lines and points: not read on either path, whatever they hold (tinyobjloader would refuse a
  // comment, an index 0, a word, blanks)
  EXPECT_TRUE(same_on("lines_and_points", quad + "vt 0 0\nvn 0 0 1\nl 1 2\nf 1 2 3\nl 1/1 2/1 -1/1\n"
                                                 "p 1 2 3 4\np -1//1\nl 1/1/1 99\nl\np \nf 2 3 4\n"
                                                 "l 1 2 # edge\nl 1 0\n\tp 1 x\np \t\nl\t\n"));
  // vertex colours: three numbers after the position; fewer, a w, or a comment: white
  EXPECT_TRUE(same_on("colors",
                      "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 1\nv 0 1 0\nv 1 1 0 0.25\nv 0 0 1 0.5 0.5\n"
                      "v 1 0 1 # c\nv 0 1 1 0.1 0.2 0.3 1\nv 2 2 2 -1 2 +0.5\nf 1 2 3\nf 4 5 6 7 8\n"));
  EXPECT_TRUE(same_on("colors_late", quad + "f 1 2 3\nv 5 5 5 0 1 0\nf 1 2 9\n"));
  EXPECT_TRUE(same_on("smoothing", quad + "s 1\nf 1 2 3\nf 1 2 3 4 5\ns off\nf 1 2 3\ns 3\nf 2 3 4\n"));
  // handed to the reference, which must still give its own result or error
  const std::pair<const char*, std::string> handed[] = {
      {"forward", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"},
      {"lone_cr", quad + "f 1 2 3\rf 2 3 4\r"},
      {"color_not_plain", quad + "v 0 0 0 1.5x 0 0\nf 1 2 3\n"},
      {"color_long_exponent", quad + "v 0 0 0 1 0 0e0000001000000041\nf 1 2 3\n"},
      {"smoothing_atoi", quad + "s 1.5\nf 1 2 3\ns -2\nf 1 2 3\ns on\nf 1 2 3\n"},
      {"bad_index", quad + "f 1 2 9\n"},
      {"zero_index", quad + "f 0 1 2\n"},
      {"nan", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"zero_times_huge_exponent", "v 0e1000 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"ten_digit_exponent", "v 0e2147483649 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"vt_long_exponent", quad + "vt 0 0e0000001000000041\nf 1 2 3\n"},
      {"unread_token_long_exponent", quad + "vt 0 4e00 0 4e000100\nv 0 0 0 1 0e999\nf 1 2 3\n"},
      {"vt_second_beyond_float", quad + "vt 0 1e39\nf 1/1 2/1 3/1\n"},
      {"vt_comment", quad + "vt 0.5 # c\nf 1/1 2/1 3/1\n"},
      {"tag_long_exponent", quad + "f 1 2 3\nt crease 0/1/0 0e0000001000000041\n"},
      {"partial_number", "v 1.5x 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"slashes", quad + "f 1// 2// 3//\n"},
      {"vt_word", quad + "vt 0.5 abc\nf 1/1 2/1 3/1\n"},
      {"no_faces", quad},
  };
  for (const auto& [name, obj] : handed) same_on(name, obj);
}

// In 3 pieces the face's piece holds one vt, so its relative -2 is -1 inside the piece (a vt of the
// piece before) until the join fixes it up: it must not read as "no texcoord" (the face lost its
// texcoords and the fix-up wrote past an empty array). Found by the obj fuzzer.
TEST(ObjFast, ARelativeIndexThatIsMinusOneInsideItsPieceIsKept) {
  const std::string quad = "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 3 1\nv 0 3 1\n";
  EXPECT_TRUE(same_on("relative_minus_one", quad + "vt 0 0\nvt 0 0\nvt$\nf -4 -3/-2 -1\n"));
  EXPECT_TRUE(
      expect_same_as_reference(RAYVEC_TEST_DATA + std::string("/fuzz/obj_relative_index_minus_one.obj")));
}

// Random files from a grammar of the fast subset and its near misses.
TEST(ObjFast, SameAsTinyobjloaderOnRandomFiles) {
  std::mt19937 rng(7);
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  int taken = 0;
  const char* numbers[] = {"0", "1", "-2.5", "0.125", "+3", "1e-2", ".5", "7.", "1.0000001", "-0"};
  for (int file = 0; file < 40; ++file) {
    std::string text;
    int v = 0, vt = 0, vn = 0;
    for (int line = 0; line < 60; ++line) {
      const int kind = pick(12);
      if (kind < 4) {
        text += "v";
        for (int k = 0; k < 3; ++k) text += std::string(" ") + numbers[pick(10)];
        ++v;
      } else if (kind == 4) {
        text += std::string("vt ") + numbers[pick(10)] + " " + numbers[pick(10)];
        ++vt;
      } else if (kind == 5) {
        text += std::string("vn 0 ") + numbers[pick(10)] + " 1";
        ++vn;
      } else if (kind < 10 && v > 0) {
        text += "f";
        const int corners = 3 + pick(3) / 2;  // mostly triangles, some quads
        const int form = pick(4);             // v, v/vt, v//vn, v/vt/vn for the whole face
        for (int c = 0; c < corners; ++c) {
          const auto index = [&](int count) {
            const int i = pick(count);
            return std::to_string(pick(2) ? i + 1 : i - count);  // absolute or relative
          };
          text += " " + index(v);
          if ((form == 1 || form == 3) && vt > 0) text += "/" + index(vt);
          if ((form == 2 || form == 3) && vn > 0) text += (form == 2 || vt == 0 ? "//" : "/") + index(vn);
        }
      } else if (kind == 10) {
        text += pick(2) ? "usemtl a" : "usemtl b";
      } else {
        text += pick(2) ? "mtllib m.mtl" : "g part";
      }
      text += pick(5) ? "\n" : "\r\n";
    }
    SCOPED_TRACE(text);
    taken += same_on("random" + std::to_string(file), text);
  }
  EXPECT_GE(taken, 30);
}

}  // namespace
}  // namespace rayvec
