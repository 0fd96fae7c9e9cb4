// written_material_name, material_key and text_for_tinyobjloader: a `usemtl` line names the whole rest of its
// line, and the text handed to tinyobjloader keeps every line and line end.
#include "scene/material_names.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayvec {
namespace {

bool no_file(const std::string&) { return false; }  // no MTL file exists

TEST(MaterialNames, UsemtlNamesTheRestOfItsLine) {
  EXPECT_EQ(written_material_name(" Material #25"), "Material #25");
  EXPECT_EQ(written_material_name("\t Hard Shiny  Plastic \t\r"), "Hard Shiny  Plastic");
  EXPECT_EQ(written_material_name("red"), "red");  // `usemtlred`, as tinyobjloader reads it too
  EXPECT_EQ(written_material_name("   "), "");
}

TEST(MaterialNames, KeysHaveNoBlanksAndGiveTheNameBack) {
  for (const std::string name : {"red", "Material #25", "a\tb  c", ""}) {
    const std::string key = material_key(name);
    EXPECT_EQ(key.find_first_of(" \t"), std::string::npos) << name;
    EXPECT_EQ(material_name(key), std::string(name == "a\tb  c" ? "a b  c" : name));
  }
  EXPECT_EQ(material_key("red"), "red");
  EXPECT_NE(material_key("Material #25"), material_key("Material #26"));
}

TEST(MaterialNames, OnlyUsemtlLinesAreRewrittenAndLineEndsStay) {
  const std::string text =
      "v 0 0 0\r\nusemtl Material #25\r\n  usemtl\tA B \nusemtlC D\rg a b\nf 1 2 3\n# usemtl x y\nusemtl";
  const std::string want = std::string("v 0 0 0\r\nusemtl Material\x1f#25\r\n  usemtl A\x1f") +
                           "B\nusemtl C\x1f" + "D\rg a b\nf 1 2 3\n# usemtl x y\nusemtl ";
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader(text, lines, no_file), want);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].line, 2u);
  EXPECT_EQ(lines[0].key, "Material\x1f#25");
  EXPECT_EQ(lines[1].line, 3u);
  EXPECT_EQ(lines[2].line, 4u);  // a lone CR ends a line too
  EXPECT_EQ(lines[2].key,
            "C\x1f"
            "D");
  EXPECT_EQ(lines[3].line, 8u);
  EXPECT_EQ(lines[3].key, "");
  lines.clear();
  EXPECT_EQ(text_for_tinyobjloader("f 1 2 3\n", lines, no_file), "f 1 2 3\n");
  EXPECT_EQ(text_for_tinyobjloader("", lines, no_file), "");
  EXPECT_TRUE(lines.empty());
}

TEST(MaterialNames, MtllibBackslashesAreSeparatorsUnlessTheyEscapeASpace) {
  EXPECT_EQ(mtllib_text("..\\mats\\a.mtl", no_file), "../mats/a.mtl");
  EXPECT_EQ(mtllib_text("C:\\Users\\me\\m.mtl b.mtl", no_file), "C:/Users/me/m.mtl b.mtl");
  EXPECT_EQ(mtllib_text("a\\ b.mtl", no_file), "a\\ b.mtl");
  EXPECT_EQ(mtllib_text("end\\", no_file), "end/");
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader(
                "mtllib ..\\m\\a.mtl\r\n\tmtllib\ta\\ b\\c.mtl\nmtllibx\\y\n# mtllib a\\b\n", lines, no_file),
            "mtllib ../m/a.mtl\r\n\tmtllib\ta\\ b/c.mtl\nmtllibx\\y\n# mtllib a\\b\n");
  EXPECT_TRUE(lines.empty());
}

TEST(MaterialNames, LinesAndPointsReachTinyobjloaderEmpty) {
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader("l 1 2 # edge\r\n\tp 1 0\nf 1 2 3\nl\np\nlx 1\npoly 2\n", lines, no_file),
            "\r\n\nf 1 2 3\nl\np\nlx 1\npoly 2\n")
      << "only what tinyobjloader reads as a line or point: the keyword and a blank";
}

TEST(MaterialNames, AnMtllibLineThatNamesOneFileWithSpacesStaysOneName) {
  std::vector<std::string> asked;
  const MtlFileExists exists = [&](const std::string& name) {
    asked.push_back(name);
    return name == "Low Poly Tree.mtl" || name == "dir/my m.mtl";
  };
  EXPECT_EQ(mtllib_text("Low Poly Tree.mtl", exists), "Low\\ Poly\\ Tree.mtl");
  EXPECT_EQ(mtllib_text("  Low Poly Tree.mtl ", exists), "Low\\ Poly\\ Tree.mtl") << "outer blanks dropped";
  EXPECT_EQ(mtllib_text("dir\\my m.mtl", exists), "dir/my\\ m.mtl") << "separators first";
  EXPECT_EQ(mtllib_text("a.mtl Low Poly Tree.mtl", exists), "a.mtl Low Poly Tree.mtl") << "names as written";
  asked.clear();
  EXPECT_EQ(mtllib_text("Low\\ Poly Tree.mtl", exists), "Low\\ Poly Tree.mtl") << "escapes: as written";
  EXPECT_EQ(mtllib_text("Tree.mtl", exists), "Tree.mtl");
  EXPECT_TRUE(asked.empty()) << "one name, or escapes written: nothing to ask";
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader("mtllib Low Poly Tree.mtl\r\nusemtl a\n", lines, exists),
            "mtllib Low\\ Poly\\ Tree.mtl\r\nusemtl a\n");
}

TEST(MaterialNames, UnknownMaterialWarningsReadBack) {
  std::string key;
  std::size_t line = 7;
  EXPECT_TRUE(parse_unknown_material(unknown_material_text("Material\x1f#25", 42), key, line));
  EXPECT_EQ(key, "Material\x1f#25");
  EXPECT_EQ(line, 42u);
  EXPECT_TRUE(parse_unknown_material("material [ '' ] not found in .mtl", key, line));  // tinyobjloader's
  EXPECT_EQ(key, "");
  EXPECT_EQ(line, 0u);
  EXPECT_FALSE(parse_unknown_material("material file x.mtl not found", key, line));
  EXPECT_FALSE(parse_unknown_material("material [ 'a' ] not found in .mtl (line x)", key, line));
}

}  // namespace
}  // namespace rayvec
