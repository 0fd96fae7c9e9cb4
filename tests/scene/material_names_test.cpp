// usemtl_name, material_key and with_material_keys: a `usemtl` line names the whole rest of its
// line, and the text handed to tinyobjloader keeps every line and line end.
#include "scene/material_names.h"

#include <gtest/gtest.h>

#include <string>

namespace rayvec {
namespace {

TEST(MaterialNames, UsemtlNamesTheRestOfItsLine) {
  EXPECT_EQ(usemtl_name(" Material #25"), "Material #25");
  EXPECT_EQ(usemtl_name("\t Hard Shiny  Plastic \t\r"), "Hard Shiny  Plastic");
  EXPECT_EQ(usemtl_name("red"), "red");  // `usemtlred`, as tinyobjloader reads it too
  EXPECT_EQ(usemtl_name("   "), "");
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
  EXPECT_EQ(with_material_keys(text), want);
  EXPECT_EQ(with_material_keys("f 1 2 3\n"), "f 1 2 3\n");
  EXPECT_EQ(with_material_keys(""), "");
}

}  // namespace
}  // namespace rayvec
