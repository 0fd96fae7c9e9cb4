// Failures under `mpirun -np 2`: bad input stops every rank with exit 2 and one message; a rank that
// fails or dies stops every rank with a message naming it; Ctrl-C stops the job. None leaves an
// output file or a temporary. The failing and dying ranks are made by the test hooks
// RAYVEC_TEST_FAIL_RANK and RAYVEC_TEST_KILL_RANK (docs/distributed.md#testing-failures).
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>

#include "distributed/mpi_run.h"

extern char** environ;

namespace rayvec {
namespace {

const std::string kScene = std::string(RAYVEC_SOURCE_DIR) + "/scenes/whitted.json";

// Processes whose command line mentions `text`.
int processes_naming(const std::string& text) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string cmdline = test::read_file(e.path().string() + "/cmdline");
    n += e.path().filename() != std::to_string(::getpid()) && cmdline.find(text) != std::string::npos;
  }
  return n;
}

TEST(MpiFailures, BadSceneExitsTwoWithTheMessageOnce) {
  const std::string dir = test::temp_dir("mpi_bad_scene");
  test::write_file(dir + "/bad.json", "{\n  \"camera\": 5\n}\n");
  const auto r = test::run_mpi("render '" + dir + "/bad.json' -o '" + dir + "/out.png'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(test::count_of(r.err, "bad.json:2: camera"), 1) << r.err;
  EXPECT_EQ(test::entries_of(dir), "bad.json ");
}

// The rays are read by rank 0 alone: its error stops rank 1, which never saw the file.
TEST(MpiFailures, BadRaysReadByRankZeroStopEveryRank) {
  const std::string dir = test::temp_dir("mpi_bad_rays");
  test::write_file(dir + "/rays.csv", "0,0,-1,0,0,1\n0,0,-1,0,0\n");
  const std::string mesh = std::string(RAYVEC_SOURCE_DIR) + "/scenes/models/cube.obj";
  const auto r =
      test::run_mpi("hits --mesh '" + mesh + "' --rays '" + dir + "/rays.csv' -o '" + dir + "/hits.csv'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(test::count_of(r.err, "rays.csv:2: "), 1) << r.err;
  EXPECT_EQ(test::entries_of(dir), "rays.csv ");
}

TEST(MpiFailures, FailingRankStopsEveryRankAndIsNamed) {
  const std::string dir = test::temp_dir("mpi_fail_rank");
  const auto r = test::run_mpi("render '" + kScene + "' --width 256 --height 256 -q -o '" + dir + "/out.png'",
                               "-x RAYVEC_TEST_FAIL_RANK=1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("rayvec: rank 1 of 2: RAYVEC_TEST_FAIL_RANK"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rank 1 of 2 failed (exit status 1)"), std::string::npos) << r.err;
  EXPECT_EQ(test::entries_of(dir), "");
}

TEST(MpiFailures, DyingRankStopsEveryRankAndIsNamed) {
  const std::string dir = test::temp_dir("mpi_kill_rank");
  const std::string mesh = std::string(RAYVEC_SOURCE_DIR) + "/scenes/models/cube.obj";
  test::write_file(dir + "/rays.csv", "0,0,-3,0,0,1\n1,1,-3,0,0,1\n");
  for (const std::string& command :
       {"render '" + kScene + "' --width 256 --height 256 -q -o '" + dir + "/out.png'",
        "hits --mesh '" + mesh + "' --rays '" + dir + "/rays.csv' -o '" + dir + "/out.csv'"}) {
    const auto r = test::run_mpi(command, "-x RAYVEC_TEST_KILL_RANK=1");
    EXPECT_NE(r.status, 0) << command;
    EXPECT_NE(r.err.find("rank 1"), std::string::npos) << r.err;
    EXPECT_EQ(test::entries_of(dir), "rays.csv ") << command;
  }
}

TEST(MpiFailures, SigintToMpirunLeavesNothing) {
  const std::string dir = test::temp_dir("mpi_sigint");
  test::write_file(dir + "/out.png", "old\n");
  const std::string cmd = test::mpirun_prefix() + "'" + RAYVEC_CLI + "' render '" + kScene +
                          "' --width 512 --height 512 --spp 64 -o '" + dir + "/out.png' >'" + dir +
                          "/stdout' 2>'" + dir + "/stderr'";
  // Its own process group, like a job started from a shell, so the test can signal it as Ctrl-C does.
  const char* argv[] = {"sh", "-c", cmd.c_str(), nullptr};
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, &attr, const_cast<char**>(argv), environ), 0);
  posix_spawnattr_destroy(&attr);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (test::read_file(dir + "/stdout").find("scene:") == std::string::npos &&
         std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(-pid, SIGINT);
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  EXPECT_FALSE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << test::read_file(dir + "/stderr");
  EXPECT_EQ(test::read_file(dir + "/out.png"), "old\n");
  EXPECT_EQ(test::entries_of(dir).find(".tmp-"), std::string::npos) << test::entries_of(dir);
  // No rank outlives the job.
  EXPECT_EQ(processes_naming(dir), 0);
}

}  // namespace
}  // namespace rayvec
