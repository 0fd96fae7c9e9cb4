// written_material_name, material_key, mtllib_text: a `usemtl` line names the whole rest of its
// line; an `mtllib` line's names as tinyobjloader is to split them.
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

TEST(MaterialNames, MtllibBackslashesAreSeparatorsUnlessTheyEscapeASpace) {
  EXPECT_EQ(mtllib_text("..\\mats\\a.mtl", no_file), "../mats/a.mtl");
  EXPECT_EQ(mtllib_text("C:\\Users\\me\\m.mtl b.mtl", no_file), "C:/Users/me/m.mtl b.mtl");
  EXPECT_EQ(mtllib_text("a\\ b.mtl", no_file), "a\\ b.mtl");
  EXPECT_EQ(mtllib_text("end\\", no_file), "end/");
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
