// ObjSample: its cuts are line ends that cover the text exactly, in order, and follow the parse cost;
// its counts are close to the true ones.
#include "scene/obj_sample.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayvec {
namespace {

// `vertices` vertex lines, then `faces` triangle lines.
std::string mesh_text(int vertices, int faces) {
  std::string text;
  for (int i = 0; i < vertices; ++i) text += "v 0.123456 -1.654321 " + std::to_string(i) + ".5\n";
  for (int i = 0; i < faces; ++i)
    text += "f " + std::to_string(i % vertices + 1) + " " + std::to_string((i + 1) % vertices + 1) + " 3\n";
  return text;
}

void expect_whole_lines_in_order(std::string_view text, const std::vector<std::string_view>& pieces) {
  ASSERT_FALSE(pieces.empty());
  const char* at = text.data();
  for (const std::string_view piece : pieces) {
    EXPECT_EQ(piece.data(), at);
    EXPECT_TRUE(piece.empty() ? text.empty()
                              : piece.back() == '\n' || piece.data() + piece.size() == text.end());
    at += piece.size();
  }
  EXPECT_EQ(at, text.data() + text.size());
}

TEST(ObjSample, CutsAreLineEndsCoveringTheText) {
  for (const std::string& text : {mesh_text(3000, 6000), mesh_text(10, 5), std::string("v 1 2 3"),
                                  std::string("# one long line") + std::string(300000, 'x'), std::string()})
    for (int pieces = 1; pieces <= 5; ++pieces) {
      const std::vector<std::string_view> cut = ObjSample(text).split(pieces);
      EXPECT_LE(cut.size(), static_cast<std::size_t>(std::max(pieces, 1)));
      for (std::size_t i = 0; i + 1 < cut.size(); ++i) EXPECT_FALSE(cut[i].empty());
      expect_whole_lines_in_order(text, cut);
    }
}

TEST(ObjSample, CountsAreCloseToTheTruth) {
  const std::string text = mesh_text(100000, 200000);
  const ObjSample sample(text);
  const ObjCounts all = sample.before(text.size()), room = sample.capacity();
  EXPECT_NEAR(double(all.positions), 100000.0, 10000.0);
  EXPECT_NEAR(double(all.triangles), 200000.0, 20000.0);
  EXPECT_EQ(all.normals, 0u);
  EXPECT_GE(room.positions, 100000u);
  EXPECT_GE(room.triangles, 200000u);
  const ObjCounts half = sample.before(text.find("\nf ") + 1);  // where the faces begin
  EXPECT_NEAR(double(half.positions), 100000.0, 10000.0);
  EXPECT_LT(half.triangles, 20000u);
}
}  // namespace
}  // namespace rayvec
