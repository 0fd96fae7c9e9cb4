// `rayvec bench obj` runs at a tiny size (so the benchmark cannot rot): it prints one row per way,
// each loaded by the reader it names (the reference by tinyobjloader, the others by the fast
// reader), and bad usage exits 2.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "test_support.h"

namespace rayvec {
namespace {

// Whether `out` has the row `way`, six times, `reader`.
bool row_is(const std::string& out, const std::string& way, const std::string& reader) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string first, word;
    if (!(words >> first) || first != way) continue;
    int numbers = 0;
    while (words >> word && word.find_first_not_of("0123456789.") == std::string::npos) ++numbers;
    std::string rest;
    return numbers == 6 && word == reader && !(words >> rest);
  }
  return false;
}

TEST(BenchObj, TinyRunPrintsEveryWayAndTheFastReaderTakesTheFile) {
  const std::string obj = test::temp_dir("bench_obj") + "/tetra.obj";
  test::write_file(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
  const auto r = test::run_cli("bench obj " + obj + " --repeats 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("4 triangles"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fast reader: yes"), std::string::npos) << r.out;
  // each way names the reader that loaded the file: the reference must be tinyobjloader
  EXPECT_TRUE(row_is(r.out, "reference", "tinyobjloader")) << r.out;
  for (const char* way : {"fast-1", "fast-2"})
    EXPECT_TRUE(row_is(r.out, way, "fast")) << way << " in " << r.out;
}

TEST(BenchObj, FileOutsideTheSubsetFallsBackAndBadUsageExits2) {
  // `s 1.5` (tinyobjloader reads group 1) is outside the fast reader's subset
  const std::string obj = test::temp_dir("bench_obj_subset") + "/outside.obj";
  test::write_file(obj, "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nl 1 2\ns 1.5\nf 1 2 3 4 5\n");
  const auto r = test::run_cli("bench obj " + obj + " --repeats 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("fast reader: no"), std::string::npos) << r.out;
  EXPECT_EQ(test::run_cli("bench obj " + obj + " --repeats 0").status, 2);
  EXPECT_EQ(test::run_cli("bench obj " + obj + ".missing").status, 2);
}

}  // namespace
}  // namespace rayvec
