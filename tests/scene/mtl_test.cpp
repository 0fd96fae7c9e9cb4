// The MTL reader shared by the OBJ loaders: parsing with line numbers, the value ranges applied
// after parsing, texture names as exporters write them, and the limits every input file has.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.h"
#include "scene/mtl_file.h"
#include "scene/mtl_parser.h"
#include "scene/mtl_validate.h"
#include "scene/texture_path.h"
#include "test_support.h"

namespace rayvec {
namespace {

bool contains(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& l : lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}

std::string error_of(const std::string& text) {
  try {
    parse_mtl(text, "m.mtl");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MtlParser, ReadsValuesWithTheirLines) {
  const auto m = parse_mtl(
      "# comment\nnewmtl glass  \nKd 0.1 0.2 0.3\nKs 0.5\nNi 1.5\nTr 0.25\nillum 7\n"
      "map_Kd -s 2 2 1 -bm 0.5 my \"odd\" tex.png\nnewmtl Hard Shiny Plastic\r\nd 0.5\r\nTr 0.9\r\n",
      "m.mtl");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].material.name, "glass");
  EXPECT_EQ(m[0].material.Kd.y, 0.2f);
  EXPECT_EQ(m[0].material.Ks.z, 0.5f);  // one number: grey
  EXPECT_EQ(m[0].material.d, 0.75f);    // 1 - Tr
  EXPECT_EQ(m[0].material.illum, 7);
  EXPECT_EQ(m[0].material.map_Kd, "my \"odd\" tex.png");
  EXPECT_EQ(m[0].lines.Kd, 3u);
  EXPECT_EQ(m[0].lines.map_Kd, 8u);
  EXPECT_EQ(m[1].material.name, "Hard Shiny Plastic");
  EXPECT_EQ(m[1].material.d, 0.5f);  // `d` wins over a later `Tr`
  EXPECT_EQ(m[1].lines.newmtl, 9u);
  EXPECT_EQ(parse_mtl("newmtl q\nmap_Kd \"a b.png\"\n", "m.mtl")[0].material.map_Kd, "a b.png");
}

TEST(MtlParser, TextureScaleAndOffsetAreKeptAndOtherOptionsSkipped) {
  const auto texture = [](const std::string& line) {
    return parse_mtl("newmtl m\n" + line + "\n", "m.mtl")[0].material;
  };
  const Material both = texture("map_Kd -s 2 3 1 -bm 0.5 -o 0.5 -0.25 0 -clamp on tiles.png");
  EXPECT_EQ(both.map_Kd, "tiles.png");
  EXPECT_EQ(both.map_Kd_scale, (std::array<float, 2>{2, 3}));
  EXPECT_EQ(both.map_Kd_offset, (std::array<float, 2>{0.5f, -0.25f}));
  const Material one = texture("map_Kd -s 4 -o 0.5 a.png");  // v and w optional: their defaults
  EXPECT_EQ(one.map_Kd, "a.png");
  EXPECT_EQ(one.map_Kd_scale, (std::array<float, 2>{4, 1}));
  EXPECT_EQ(one.map_Kd_offset, (std::array<float, 2>{0.5f, 0}));
  const Material none = texture("map_Kd -mm 0 1 -t 1 1 1 b.png");
  EXPECT_EQ(none.map_Kd, "b.png");
  EXPECT_EQ(none.map_Kd_scale, (std::array<float, 2>{1, 1}));
  EXPECT_EQ(none.map_Kd_offset, (std::array<float, 2>{0, 0}));
  const Material later = texture("map_Kd -s 2 2 1 a.png\nmap_Kd b.png");
  EXPECT_EQ(later.map_Kd, "b.png");
  EXPECT_EQ(later.map_Kd_scale, (std::array<float, 2>{1, 1})) << "a later map_Kd replaces the options too";
}

TEST(MtlParser, NonFiniteNumbersNameTheLine) {
  EXPECT_NE(error_of("newmtl a\nKd 1e39 0 0\n").find("m.mtl:2: `Kd` value '1e39' is not a finite number"),
            std::string::npos);
  EXPECT_NE(error_of("newmtl a\n\nNi nan\n").find("m.mtl:3: `Ni` value 'nan'"), std::string::npos);
  EXPECT_NE(error_of("newmtl a\nNs x\n").find("m.mtl:2:"), std::string::npos);
  EXPECT_NE(error_of("newmtl a\nKs 1 1\n").find("m.mtl:2: `Ks` needs a number"), std::string::npos);
}

TEST(MtlValidate, OutOfRangeValuesAreClampedWithAWarningNamingTheLine) {
  auto m =
      parse_mtl("newmtl a\nNi -1\nKd 1e38 -2 0.5\nKs 1e38\nKe 1e30 0 0\nNs 1e38\nd 3\nillum 7\n", "m.mtl");
  std::vector<std::string> w;
  validate_mtl_material(m[0], "m.mtl", w);
  const Material& mat = m[0].material;
  EXPECT_EQ(mat.Ni, kMinIor);
  EXPECT_EQ(mat.Kd.x, 1.0f);
  EXPECT_EQ(mat.Kd.y, 0.0f);
  EXPECT_EQ(mat.Kd.z, 0.5f);
  EXPECT_EQ(mat.Ks.x, 1.0f);
  EXPECT_EQ(mat.Ke.x, kMaxEmission);
  EXPECT_EQ(mat.Ns, kMaxShininess);
  EXPECT_EQ(mat.d, 1.0f);
  EXPECT_TRUE(contains(w, "m.mtl:2: material 'a': `Ni -1` is outside")) << w.size();
  EXPECT_TRUE(contains(w, "m.mtl:3: material 'a': `Kd 1e+38 -2 0.5` has a component outside 0..1"));
  EXPECT_TRUE(contains(w, "m.mtl:7: material 'a': `d 3`"));
  EXPECT_EQ(w.size(), 6u);
}

TEST(MtlValidate, IllumOutsideTheMtlModelsIsAWarning) {
  for (const std::string value : {"11", "-1", "x"}) {
    auto m = parse_mtl("newmtl a\nKd 1 1 1\nillum " + value + "\n", "m.mtl");
    std::vector<std::string> w;
    validate_mtl_material(m[0], "m.mtl", w);
    EXPECT_EQ(m[0].material.illum, 2) << value;
    ASSERT_EQ(w.size(), 1u) << value;
    EXPECT_NE(w[0].find("m.mtl:3: material 'a': `illum " + value + "`"), std::string::npos) << w[0];
  }
}

TEST(MtlValidate, UnusedNiZeroIsQuiet) {
  auto m = parse_mtl("newmtl a\nNi 0\nillum 2\n", "m.mtl");
  std::vector<std::string> w;
  validate_mtl_material(m[0], "m.mtl", w);
  EXPECT_TRUE(w.empty());
  EXPECT_EQ(m[0].material.Ni, 1.0f);
}

TEST(TexturePath, WindowsSeparatorsAbsolutePathsAndQuotesResolve) {
  const std::string dir = test::temp_dir("texture_path");
  std::filesystem::create_directories(dir + "/sub dir");
  test::write_file(dir + "/sub dir/a b.png", "x");
  test::write_file(dir + "/plain.png", "x");
  EXPECT_EQ(resolve_named_file(".\\sub dir\\a b.png", dir), dir + "/sub dir/a b.png");
  EXPECT_EQ(resolve_named_file("sub dir/a b.png", dir), dir + "/sub dir/a b.png");
  EXPECT_EQ(resolve_named_file(dir + "/plain.png", "/elsewhere"), dir + "/plain.png");
  // An exporter's absolute path from another machine: the file beside the MTL.
  EXPECT_EQ(resolve_named_file("C:\\Users\\me\\models\\plain.png", dir), dir + "/plain.png");
  EXPECT_EQ(resolve_named_file("/home/me/plain.png", dir), dir + "/plain.png");
  EXPECT_EQ(resolve_named_file("nope.png", dir), dir + "/nope.png");
}

TEST(TexturePath, NamesWrittenOnACaseInsensitiveFileSystemResolve) {
  const std::string dir = test::temp_dir("texture_path_case");
  std::filesystem::create_directories(dir + "/textures");
  test::write_file(dir + "/textures/wood.jpg", "x");
  test::write_file(dir + "/plain.png", "x");
  test::write_file(dir + "/Twin.png", "x");
  test::write_file(dir + "/twin.PNG", "x");
  EXPECT_EQ(resolve_named_file("Textures\\Wood.JPG", dir), dir + "/textures/wood.jpg");
  EXPECT_EQ(resolve_named_file("TEXTURES/wood.jpg", dir), dir + "/textures/wood.jpg");
  EXPECT_EQ(resolve_named_file("PLAIN.png", dir), dir + "/plain.png");
  EXPECT_EQ(resolve_named_file("C:\\Users\\me\\Plain.PNG", dir), dir + "/plain.png");
  // an exact name wins; of several that differ only in case, the first in name order
  EXPECT_EQ(resolve_named_file("twin.PNG", dir), dir + "/twin.PNG");
  EXPECT_EQ(resolve_named_file("TWIN.png", dir), dir + "/Twin.png");
  // no match: the name as written, for the message
  EXPECT_EQ(resolve_named_file("textures/oak.jpg", dir), dir + "/textures/oak.jpg");
  EXPECT_EQ(resolve_named_file("Nope/wood.jpg", dir), dir + "/Nope/wood.jpg");
}

TEST(TexturePath, OnlyReadableRegularFilesAreUsed) {
  const std::string dir = test::temp_dir("texture_problem");
  test::write_file(dir + "/t.png", "x");
  EXPECT_EQ(texture_file_problem(dir + "/t.png"), "");
  EXPECT_EQ(texture_file_problem(dir + "/nope.png"), "not found");
  EXPECT_EQ(texture_file_problem("/dev/zero"), "is not a regular file");
  EXPECT_EQ(texture_file_problem(dir), "is not a regular file");
  ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
  EXPECT_EQ(texture_file_problem(dir + "/fifo"), "is not a regular file");
}

TEST(MtlFile, TexturesThatCannotBeUsedAreWarningsNamingTheLine) {
  const std::string dir = test::temp_dir("mtl_file_textures");
  test::write_file(dir + "/t.png", "x");
  test::write_file(dir + "/m.mtl",
                   "newmtl a\nmap_Kd /dev/zero\nnewmtl b\nmap_Kd .\\t.png\nnewmtl c\n\nmap_Kd gone.png\n");
  std::vector<std::string> w;
  const auto m = read_mtl_file(dir + "/m.mtl", w);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].map_Kd, "");
  EXPECT_EQ(m[1].map_Kd, dir + "/t.png");
  EXPECT_EQ(m[2].map_Kd, "");
  EXPECT_TRUE(
      contains(w, dir + "/m.mtl:2: material 'a': texture '/dev/zero' (/dev/zero) is not a regular file"));
  EXPECT_TRUE(
      contains(w, dir + "/m.mtl:7: material 'c': texture 'gone.png' (" + dir + "/gone.png) not found"));
}

// Sets RAYVEC_MAX_INPUT_MB for one scope.
struct InputLimit {
  explicit InputLimit(const char* mb) { setenv("RAYVEC_MAX_INPUT_MB", mb, 1); }
  ~InputLimit() { unsetenv("RAYVEC_MAX_INPUT_MB"); }
};

std::string read_error(const std::string& path) {
  std::vector<std::string> w;
  try {
    read_mtl_file(path, w);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MtlFile, TheInputLimitAndTheNulCheckApply) {
  const std::string dir = test::temp_dir("mtl_file_limits");
  {  // sparse: no disk space, judged by its size before any byte is read
    std::ofstream big(dir + "/big.mtl");
    big.seekp(3000000);
    big.put('\n');
  }
  {
    const InputLimit limit("2");
    EXPECT_NE(read_error(dir + "/big.mtl").find("larger than the 2 MB input limit"), std::string::npos);
  }
  test::write_file(dir + "/nul.mtl", std::string("newmtl a\n\0\0\0", 12));
  EXPECT_NE(read_error(dir + "/nul.mtl").find("nul.mtl:2: contains a NUL byte"), std::string::npos)
      << read_error(dir + "/nul.mtl");
}

}  // namespace
}  // namespace rayvec
