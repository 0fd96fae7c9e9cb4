// Command-line values outside what rayvec can honour are refused before any work (exit 2, the
// option named, nothing written): --threads beyond kMaxThreads made libgomp crash or exit 1 and
// left the output's temporary behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "bvh/bvh_scenes.h"
#include "platform/isa.h"
#include "test_support.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

bool empty_but(const std::string& dir, std::size_t n) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator())) == n;
}

// Each of `bad` appended to `command` exits 2 with `message` on stderr.
void expect_refused(const std::string& command, std::initializer_list<const char*> bad,
                    const std::string& message) {
  for (const char* b : bad) {
    const auto r = test::run_cli(command + b);
    EXPECT_EQ(r.status, 2) << b << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << b << ": " << r.err;
  }
}

TEST(OptionLimits, ThreadsAboveTheBoundAreRefusedForEveryCommand) {
  const std::string dir = test::temp_dir("option_threads");
  test::write_file(dir + "/m.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n");
  test::write_file(dir + "/r.csv", "0.2,0.2,0,0,0,1\n");
  test::write_file(dir + "/v.csv", "0,0,1\n1,0,1\n0,1,1\n");
  test::write_file(dir + "/f.csv", "0,1,2\n");
  const std::string hits = "hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv -o " + dir + "/out.csv";
  for (const std::string& args :
       {hits + " --threads 100000", hits + " --threads 33000", hits + " --threads 1025",
        "visibility --verts " + dir + "/v.csv --faces " + dir + "/f.csv -o " + dir +
            "/out.txt --threads 5000",
        "render -q " + dir + "/m.obj --width 4 --height 4 -o " + dir + "/out.png --threads 100000",
        std::string("accuracy --threads 100000"), std::string("bench paper --threads 100000"),
        "bench rays " + dir + "/m.obj --threads 100000"}) {
    const auto r = test::run_cli(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("--threads: must be between 0 (all cores) and 1024"), std::string::npos)
        << args << ": " << r.err;
  }
  EXPECT_TRUE(empty_but(dir, 4));  // the four inputs only
  const auto r = test::run_cli(hits + " --threads 1024");
  EXPECT_EQ(r.status, 0) << r.err;
}

// bench rays' tuning options: a merged leaf holds at most 32 slots, so --merge-steps stops there;
// in range it is run and reported.
TEST(OptionLimits, BenchRaysMergeStepsAreBounded) {
  const std::string dir = test::temp_dir("option_merge_steps");
  test::write_file(dir + "/m.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n");
  const std::string bench = "bench rays " + dir + "/m.obj --size 4x4 --repeats 1 --builds 1";
  expect_refused(bench, {" --merge-steps 33", " --merge-steps -1"}, "--merge-steps: must be 0 to 32");
  const auto r = test::run_cli(bench + " --merge-steps 0 --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"merge_steps\":0"), std::string::npos) << r.out;
}

// --split-budget is a fraction of the triangles in [0, 1]; in range it is run and reported with the
// references per triangle it gave: 1 without splits, more on a mesh of long slivers.
TEST(OptionLimits, BenchRaysSplitBudgetIsAFractionAndReported) {
  const std::string dir = test::temp_dir("option_split_budget");
  const TriangleMesh mesh = test::long_slivers(3000, 7);
  std::string obj;
  for (const Vec3f& p : mesh.positions)
    obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  for (const auto& t : mesh.triangles)
    obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) +
           "\n";
  test::write_file(dir + "/m.obj", obj);
  const std::string bench = "bench rays " + dir + "/m.obj --size 4x4 --repeats 1 --builds 1 --json";
  for (const char* bad : {" --split-budget 1.5", " --split-budget -0.5", " --split-budget nan"}) {
    const auto r = test::run_cli(bench + bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
  }
  const auto none = test::run_cli(bench + " --split-budget 0");
  EXPECT_EQ(none.status, 0) << none.err;
  EXPECT_NE(none.out.find("\"split_budget\":0.000,\"references_per_tri\":1.0000"), std::string::npos)
      << none.out;
  const auto split = test::run_cli(bench);
  EXPECT_EQ(split.status, 0) << split.err;
  const std::string key = "\"split_budget\":0.300,\"references_per_tri\":";
  const std::size_t at = split.out.find(key);
  ASSERT_NE(at, std::string::npos) << split.out;
  EXPECT_GT(std::stod(split.out.substr(at + key.size())), 1.05) << split.out;
}

// --leaf-steps is 1 or 2 kernel steps (0: the default), refused beside --max-leaf or --leaf-block,
// which size the leaves themselves; in range it is run and reported where the leaves are sized to a
// SIMD kernel.
TEST(OptionLimits, BenchRaysLeafStepsAreOneOrTwoAndReported) {
  const std::string dir = test::temp_dir("option_leaf_steps");
  test::write_file(dir + "/m.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n");
  const std::string bench = "bench rays " + dir + "/m.obj --size 4x4 --repeats 1 --builds 1 --json";
  expect_refused(bench, {" --leaf-steps 3", " --leaf-steps -1"}, "--leaf-steps: must be 0, 1 or 2");
  expect_refused(bench, {" --leaf-steps 2 --max-leaf 8", " --leaf-steps 1 --leaf-block 4"},
                 "--leaf-steps: not with --max-leaf or --leaf-block");
  if (!isa_supported(Isa::avx2)) GTEST_SKIP() << "no AVX2 on this CPU: leaves are not sized to a kernel";
  const auto r = test::run_cli(bench + " --isa avx2 --leaf-steps 2");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"leaf_steps\":2"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rayvec
