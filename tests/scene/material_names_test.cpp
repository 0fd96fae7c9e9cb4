// written_material_name, material_key and text_for_tinyobjloader: a `usemtl` line names the whole rest of its
// line, and the text handed to tinyobjloader keeps every line and line end.
#include "scene/material_names.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayvec {
namespace {

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
  EXPECT_EQ(text_for_tinyobjloader(text, lines), want);
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
  EXPECT_EQ(text_for_tinyobjloader("f 1 2 3\n", lines), "f 1 2 3\n");
  EXPECT_EQ(text_for_tinyobjloader("", lines), "");
  EXPECT_TRUE(lines.empty());
}

TEST(MaterialNames, MtllibBackslashesAreSeparatorsUnlessTheyEscapeASpace) {
  EXPECT_EQ(mtllib_separators("..\\mats\\a.mtl"), "../mats/a.mtl");
  EXPECT_EQ(mtllib_separators("C:\\Users\\me\\m.mtl b.mtl"), "C:/Users/me/m.mtl b.mtl");
  EXPECT_EQ(mtllib_separators("a\\ b.mtl"), "a\\ b.mtl");
  EXPECT_EQ(mtllib_separators("end\\"), "end/");
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader(
                "mtllib ..\\m\\a.mtl\r\n\tmtllib\ta\\ b\\c.mtl\nmtllibx\\y\n# mtllib a\\b\n", lines),
            "mtllib ../m/a.mtl\r\n\tmtllib\ta\\ b/c.mtl\nmtllibx\\y\n# mtllib a\\b\n");
  EXPECT_TRUE(lines.empty());
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
