// The fast OBJ reader in pieces against itself in one piece: wherever the text is cut (every line end
// for two pieces, random cuts for three and four, and ObjSample's own cuts for 2 to 4 threads), the
// result is bit for bit the one-piece result — the same ObjModel, warnings, errors and MTL loads in the
// same order — or, for a file outside the fast subset, the same refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scene/obj_fast.h"
#include "scene/obj_sample.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

struct Result {
  bool taken = false;
  ObjModel model;
  std::string warn, err, mtl_calls;  // mtl_calls: the libraries asked for, in order
};

// Knows two libraries, m.mtl and "my m.mtl", each with materials a and b.
MtlLibraries fake_mtl(std::string& calls) {
  const auto known = [](const std::string& file) { return file == "m.mtl" || file == "my m.mtl"; };
  return {known, [&calls, known](const std::string& file, std::map<std::string, int>& by_name,
                                 std::string& warn, std::string&) {
            calls += file + ";";
            if (!known(file)) {
              warn += "no " + file + "\n";
              return false;
            }
            for (const char* name : {"a", "b"}) by_name.emplace(name, static_cast<int>(by_name.size()));
            return true;
          }};
}

Result load(std::string_view text, const std::vector<std::string_view>& pieces) {
  Result r;
  r.taken = load_obj_pieces(text, ObjSample(text), pieces, fake_mtl(r.mtl_calls), r.model, r.warn, r.err);
  return r;
}

Result load_threads(std::string_view text, int threads) {
  Result r;
  r.taken = load_obj_fast(text, threads, fake_mtl(r.mtl_calls), r.model, r.warn, r.err);
  return r;
}

void expect_identical(const Result& a, const Result& b, const std::string& what) {
  ASSERT_EQ(a.taken, b.taken) << what;
  EXPECT_EQ(a.warn, b.warn) << what;
  EXPECT_EQ(a.err, b.err) << what;
  EXPECT_EQ(a.mtl_calls, b.mtl_calls) << what;
  const ObjModel &x = a.model, &y = b.model;
  EXPECT_EQ(x.mesh.positions, y.mesh.positions) << what;  // exact: the same parse of the same text
  EXPECT_EQ(x.mesh.triangles, y.mesh.triangles) << what;
  EXPECT_EQ(x.normals, y.normals) << what;
  EXPECT_EQ(x.colors, y.colors) << what;
  EXPECT_EQ(x.texcoords, y.texcoords) << what;
  EXPECT_EQ(x.triangle_normals, y.triangle_normals) << what;
  EXPECT_EQ(x.triangle_texcoords, y.triangle_texcoords) << what;
  EXPECT_EQ(x.triangle_material, y.triangle_material) << what;
  EXPECT_EQ(x.triangle_smoothing, y.triangle_smoothing) << what;
}

// The line ends of `text`: the places a cut may go.
std::vector<std::size_t> cut_points(std::string_view text) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') out.push_back(i + 1);
  return out;
}

std::vector<std::string_view> cut_at(std::string_view text, std::vector<std::size_t> cuts) {
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::string_view> pieces;
  std::size_t start = 0;
  for (const std::size_t cut : cuts) {
    pieces.push_back(text.substr(start, cut - start));  // empty pieces too: they must not matter
    start = cut;
  }
  pieces.push_back(text.substr(start));
  return pieces;
}

// Every two-piece cut, `random` cuts into three and four pieces, and 2..4 threads; returns whether
// the fast reader took the text.
bool expect_cuts_change_nothing(std::string_view text, const std::string& name, int random = 40) {
  const Result whole = load(text, {text});
  const std::vector<std::size_t> points = cut_points(text);
  for (const std::size_t p : points)
    expect_identical(load(text, cut_at(text, {p})), whole, name + " cut " + std::to_string(p));
  std::mt19937 rng(11);
  for (int i = 0; i < random && !points.empty(); ++i) {
    std::vector<std::size_t> cuts;
    for (int k = 0; k < 2 + i % 2; ++k) cuts.push_back(points[rng() % points.size()]);
    expect_identical(load(text, cut_at(text, cuts)), whole, name + " random cuts " + std::to_string(i));
  }
  for (int threads = 2; threads <= 4; ++threads)
    expect_identical(load_threads(text, threads), whole, name + " threads " + std::to_string(threads));
  return whole.taken;
}

const std::string kQuad = "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 3 1\nv 0 3 1\n";

TEST(ObjPieces, CutsChangeNothingOnEdgeCases) {
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad + "f 1 2 3 4\nf 5 6 7 8\nf 4 3 2 1\n", "quads"));
  EXPECT_TRUE(
      expect_cuts_change_nothing(kQuad + "f -4 -3 -2\nv 9 9 9\nf -1 -2 -3 -4\nf 1 2 -1\n", "relative"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad +
                                             "vt 0.5\nvt .25 +.75 7\nvn 0 0 1\nvn -0 1e-3 1E2\n"
                                             "f 1/1 2/2 3/1\nf 1//1 2//2 3//-1\nf 1/-1/1 2/2/2 3/1/1 4/2/2\n",
                                         "attributes"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad + "vn 0 0 1\nvt 0 0\nf 1 2 3 4\nf 5 6 7\nf 4 3 2 1\n"
                                                 "f 1//1 2//1 3//1\nf 1/1 2/1 3/1 4/1\nf 5 6 7 8\n",
                                         "attributes from a later face on"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad + "vn 0 0 1\nf 1 2 3 4\nf 5 6 7\n", "attributes unused"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad +
                                             "usemtl a\nf 1 2 3\nmtllib m.mtl\nf 1 2 3\nusemtl b\nf 1 2 3\n"
                                             "usemtl nope\nf 1 2 3 4\nusemtl a\nusemtl a\nf 2 3 4\n",
                                         "materials"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad + "mtllib missing.mtl m.mtl\nmtllib m.mtl\nusemtlb\nf 1 2 3\n",
                                         "mtllibs"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad + "mtllib  my m.mtl \nusemtl a\nf 1 2 3\nmtllib my x.mtl\n",
                                         "mtllib names with spaces"));
  EXPECT_TRUE(expect_cuts_change_nothing(
      kQuad + "g\ng \no\no x\ns off\ns 1\nt x 1/0/0 5\ng a b\nf 1 2 3\ng\n", "groups"));
  EXPECT_TRUE(expect_cuts_change_nothing(
      kQuad + "f 1 2 3\nv 0 0 0 1 0 0\nv 1 1 1\nf 1 2 3 4\nv 2 2 2 0 0 1\nf 9 10 11\n",
      "colours from a later position on"));
  EXPECT_TRUE(expect_cuts_change_nothing(kQuad +
                                             "s 1\nf 1 2 3\nf 1 2 3 4\ng x\nf 5 6 7\ns\nf 1 2 3\ns off\n"
                                             "f 1 2 3 4 5\ns 12\nf 1 2 3\ns 0\nf 1 2 3\ns\t7 8\nf 4 3 2\n",
                                         "smoothing groups"));
  EXPECT_TRUE(expect_cuts_change_nothing(
      "# c\n\n  \t\nv 0 0 0 1 0 0\r\nv\t1 0 0\t\r\nv 0 1 0 # c\n f 1 2 3 \t\nvp 1 2\nf 1 2 3", "blanks"));
  EXPECT_TRUE(
      expect_cuts_change_nothing(kQuad + "vt 0 0\nvn 0 0 1\nf 1 2 3 4 5\nf 1 2 3\n"
                                         "f -1/1/1 -2/1/1 -3/1/1 -4/1/1 -5/1/1 -6/1/1\nf 8 7 6 5 4 3 2 1\n",
                                 "polygons"));
  // outside the subset in one piece: so in every cut
  EXPECT_FALSE(expect_cuts_change_nothing("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "forward"));
  EXPECT_FALSE(expect_cuts_change_nothing(kQuad + "f 1 2 3\nf -9 1 2\n", "relative before the file"));
  EXPECT_FALSE(expect_cuts_change_nothing(kQuad + "f 1 2 3\nf 1 2 9\n", "beyond the end"));
  EXPECT_FALSE(expect_cuts_change_nothing(kQuad + "f 1 2 3\rf 2 3 4\r", "lone cr"));
}

TEST(ObjPieces, CutsChangeNothingOnTestData) {
  int files = 0;
  for (const char* dir : {"/obj", "/fuzz_corpus/obj"})
    for (const auto& e : fs::recursive_directory_iterator(RAYVEC_TEST_DATA + std::string(dir))) {
      if (!e.is_regular_file() || e.path().extension() != ".obj") continue;
      std::ifstream in(e.path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      expect_cuts_change_nothing(text.str(), e.path().string(), 10);
      ++files;
    }
  EXPECT_GE(files, 4);
}

// Vertices first and faces after (the common layout, where the cost-weighted cut matters), then
// interleaved, with every corner form, quads, relative indices and material switches near the cuts.
std::string random_file(std::mt19937& rng, bool interleaved) {
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  std::string text = "mtllib m.mtl\n";
  int v = 0, vt = 0, vn = 0;
  const auto vertices = [&](int n) {
    for (int i = 0; i < n; ++i) {
      text += "v " + std::to_string(pick(100)) + ".5 -" + std::to_string(pick(9)) + " 0.125\n";
      if (pick(2)) {
        text += "vt 0." + std::to_string(pick(99)) + " 1\n";
        ++vt;
      } else {
        text += "vn 0 -0." + std::to_string(pick(99)) + " 1\n";
        ++vn;
      }
      ++v;
    }
  };
  vertices(8);
  for (int line = 0; line < 120; ++line) {
    if (interleaved && pick(4) == 0) vertices(1);
    if (pick(10) == 0) text += pick(2) ? "usemtl a\n" : "usemtl b\n";
    if (pick(20) == 0) text += "g\n";
    const int corners = 3 + pick(2);
    const int form = pick(4);  // v, v/vt, v//vn, v/vt/vn
    text += "f";
    for (int c = 0; c < corners; ++c) {
      const auto index = [&](int count) {
        const int i = pick(count);
        return std::to_string(pick(2) ? i + 1 : i - count);
      };
      text += " " + index(v);
      if ((form == 1 || form == 3) && vt > 0) text += "/" + index(vt);
      if ((form == 2 || form == 3) && vn > 0) text += (form == 2 || vt == 0 ? "//" : "/") + index(vn);
    }
    text += pick(8) ? "\n" : "\r\n";
  }
  return text;
}

TEST(ObjPieces, CutsChangeNothingOnRandomFiles) {
  std::mt19937 rng(5);
  int taken = 0;
  for (int file = 0; file < 12; ++file) {
    const std::string text = random_file(rng, file % 2 == 1);
    SCOPED_TRACE(text);
    taken += expect_cuts_change_nothing(text, "random " + std::to_string(file));
  }
  EXPECT_EQ(taken, 12);
}

// Big enough for ObjSample to sample windows (not read the whole text) and for the threads' arrays to
// be appended in place.
TEST(ObjPieces, ThreadsChangeNothingOnALargeFile) {
  std::mt19937 rng(3);
  std::string text;
  for (int i = 0; i < 80; ++i) text += random_file(rng, i % 3 == 0);
  ASSERT_GT(text.size(), std::size_t(200000));
  const Result whole = load(text, {text});
  ASSERT_TRUE(whole.taken);
  for (int threads = 2; threads <= 4; ++threads)
    expect_identical(load_threads(text, threads), whole, "threads " + std::to_string(threads));
}

}  // namespace
}  // namespace rayvec
