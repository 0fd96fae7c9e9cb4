// Command-line and input corner cases a hostile user finds: each is refused clearly before any
// work (exit 2, what is wrong, nothing written), and a failed write to standard output is exit 1.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_support.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

const std::string kTri = "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n";

void expect_refused(const test::CommandResult& r, const std::string& message) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "expected '" << message << "' in: " << r.err;
}

TEST(CliEdgeCases, StatsJsonOnTheImagePathIsRefusedBeforeRendering) {
  const std::string dir = test::temp_dir("edge_stats_json");
  test::write_file(dir + "/m.obj", kTri);
  test::write_file(dir + "/out.png", "old\n");
  auto r = test::run_cli("render -q " + dir + "/m.obj --width 8 --height 8 -o " + dir +
                         "/out.png --stats-json " + dir + "/./out.png");
  expect_refused(r, "--stats-json: " + dir + "/./out.png is the image -o writes");
  EXPECT_EQ(test::read_file(dir + "/out.png"), "old\n");
  // An unwritable --stats-json is found before the render, not after it.
  r = test::run_cli("render " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/new.png --stats-json " +
                    dir + "/nodir/s.json");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write " + dir + "/nodir/s.json"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("scene:"), std::string::npos) << "rendered first: " << r.out;
  EXPECT_FALSE(fs::exists(dir + "/new.png"));
}

TEST(CliEdgeCases, DuplicateSceneKeysAreReportedWithTheirLine) {
  const std::string dir = test::temp_dir("edge_dup_keys");
  test::write_file(dir + "/m.obj", kTri);
  test::write_file(dir + "/s.json",
                   "{\"objects\": [{\"obj\": \"m.obj\"}],\n \"camera\": {\"width\": 8,\n  \"width\": 16}}\n");
  expect_refused(test::run_cli("render -q " + dir + "/s.json -o " + dir + "/out.png"),
                 dir + "/s.json:3: duplicate key 'camera.width'");
}

TEST(CliEdgeCases, UnknownSceneIntersectorNamesTheSceneLine) {
  const std::string dir = test::temp_dir("edge_scene_intersector");
  test::write_file(dir + "/m.obj", kTri);
  test::write_file(dir + "/s.json",
                   "{\"objects\": [{\"obj\": \"m.obj\"}],\n \"render\": {\"intersector\": \"fast\"}}\n");
  expect_refused(test::run_cli("render -q " + dir + "/s.json -o " + dir + "/out.png"),
                 dir +
                     "/s.json:2: render.intersector: unknown 'fast' (choose mt, mt64, paper, watertight or "
                     "watertight64)");
}

TEST(CliEdgeCases, LoneCarriageReturnsInACsvSayWhatIsWrong) {
  const std::string dir = test::temp_dir("edge_cr_csv");
  test::write_file(dir + "/m.obj", kTri);
  test::write_file(dir + "/r.csv", "0.2,0.2,0,0,0,1\r0.2,0.2,0,0,0,1\r");
  expect_refused(test::run_cli("hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv"),
                 dir + "/r.csv:1: has a carriage return (CR) inside a line");
}

TEST(CliEdgeCases, UnknownSubcommandIsNamed) {
  auto r = test::run_cli("frobnicate --x");
  expect_refused(r, "rayvec: unknown command 'frobnicate'");
  EXPECT_NE(r.err.find("hits"), std::string::npos) << r.err;  // lists the commands
  expect_refused(test::run_cli("bench frobnicate"), "rayvec bench: unknown command 'frobnicate'");
}

TEST(CliEdgeCases, AFullStandardOutputIsExitOne) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  for (const std::string args : {"info", "--help", "hits --help"}) {
    const int raw =
        std::system(("'" + std::string(RAYVEC_CLI) + "' " + args + " >/dev/full 2>/dev/null").c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 1) << args;
  }
}

TEST(CliEdgeCases, DashReadsRaysAndVerticesFromStandardInput) {
  const std::string dir = test::temp_dir("edge_stdin");
  test::write_file(dir + "/m.obj", kTri);
  auto r = test::run_cli("hits --mesh " + dir + "/m.obj --rays -", "0.2,0.2,0,0,0,1\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("ray,tri,t,u,v\n0,0,1,", 0), 0u) << r.out;
  r = test::run_cli("hits --mesh " + dir + "/m.obj --rays -", "0.2,0.2,0,0,0\n");
  expect_refused(r, "stdin:1: found 5 fields");
  test::write_file(dir + "/f.csv", "0,1,2\n");
  r = test::run_cli("visibility --verts - --faces " + dir + "/f.csv", "0,0,1\n1,0,1\n0,1,1\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "1\n1\n1\n");
  expect_refused(test::run_cli("visibility --verts - --faces -", ""),
                 "--verts and --faces cannot both read standard input");
}

}  // namespace
}  // namespace rayvec
