// `rayvec accuracy` at a tiny size: writes the markdown report atomically, prints JSON, rejects
// bad options with exit status 2.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

namespace rayvec {
namespace {

TEST(AccuracyCli, WritesMarkdownAndJson) {
  const std::string dir = test::temp_dir("accuracy_cli");
  const std::string md = dir + "/accuracy.md";
  const auto r = test::run_cli("accuracy --scale 1 --size 8 --repeats 1 --threads 1 --json -o " + md);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"intersector\":\"watertight\""), std::string::npos);
  EXPECT_NE(r.out.find("\"name\":\"quad_diagonal\""), std::string::npos);
  const std::string text = test::read_file(md);
  EXPECT_NE(text.find("| watertight64 | scalar |"), std::string::npos);
  EXPECT_NE(text.find("random_control"), std::string::npos);
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename(), "accuracy.md") << "temporary left behind";
}

TEST(AccuracyCli, BadOptionsExitTwo) {
  EXPECT_EQ(test::run_cli("accuracy --scale 0").status, 2);
  EXPECT_EQ(test::run_cli("accuracy --size 3").status, 2);
  EXPECT_EQ(test::run_cli("accuracy --repeats 0").status, 2);
}

}  // namespace
}  // namespace rayvec
