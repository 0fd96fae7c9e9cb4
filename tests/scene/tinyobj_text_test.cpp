// text_for_tinyobjloader: the text handed to tinyobjloader keeps every line and line end; only
// `usemtl` names, `mtllib` names and line/point lines are rewritten.
#include "scene/tinyobj_text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayvec {
namespace {

bool no_file(const std::string&) { return false; }  // no MTL file exists

TEST(TinyobjText, OnlyUsemtlLinesAreRewrittenAndLineEndsStay) {
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

TEST(TinyobjText, MtllibLinesGoThroughMtllibText) {
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader(
                "mtllib ..\\m\\a.mtl\r\n\tmtllib\ta\\ b\\c.mtl\nmtllibx\\y\n# mtllib a\\b\n", lines, no_file),
            "mtllib ../m/a.mtl\r\n\tmtllib\ta\\ b/c.mtl\nmtllibx\\y\n# mtllib a\\b\n");
  EXPECT_TRUE(lines.empty());
  const MtlFileExists exists = [](const std::string& name) { return name == "Low Poly Tree.mtl"; };
  EXPECT_EQ(text_for_tinyobjloader("mtllib Low Poly Tree.mtl\r\nusemtl a\n", lines, exists),
            "mtllib Low\\ Poly\\ Tree.mtl\r\nusemtl a\n");
}

TEST(TinyobjText, LinesAndPointsReachTinyobjloaderEmpty) {
  std::vector<UsemtlLine> lines;
  EXPECT_EQ(text_for_tinyobjloader("l 1 2 # edge\r\n\tp 1 0\nf 1 2 3\nl\np\nlx 1\npoly 2\n", lines, no_file),
            "\r\n\nf 1 2 3\nl\np\nlx 1\npoly 2\n")
      << "only what tinyobjloader reads as a line or point: the keyword and a blank";
}

}  // namespace
}  // namespace rayvec
