// A real SIGINT (Ctrl-C) in the middle of slow work: rayvec exits 130, leaves no temporary behind,
// and an output file that existed before keeps its old content (main.cpp unlinks AtomicFile
// temporaries in its signal handler; the final name is only ever written by rename).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "test_support.h"

extern char** environ;

namespace rayvec {
namespace {

namespace fs = std::filesystem;

// Starts the CLI with `args`, stdout and stderr to files in `dir`; returns its pid.
pid_t spawn_cli(const std::vector<std::string>& args, const std::string& dir) {
  std::vector<std::string> all{RAYVEC_CLI};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, (dir + "/stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, (dir + "/stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, RAYVEC_CLI, &files, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&files);
  return pid;
}

// Polls `ready` every 10 ms for up to 60 s (slow under sanitizers); false if it never held.
bool wait_until(const std::function<bool()>& ready) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// Sends SIGINT and returns the exit status (128 + signal when killed by a signal).
int interrupt(pid_t pid) {
  ::kill(pid, SIGINT);
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

bool has_temporary(const std::string& dir, const std::string& stem) {
  for (const std::string& n : files_in(dir))
    if (n.rfind(stem + ".tmp-", 0) == 0) return true;
  return false;
}

// m.obj (2000 triangles) and r.csv (a million rays) in dir: seconds of brute-force tracing with the
// output already open.
void write_slow_hits_inputs(const std::string& dir) {
  std::string obj, rays;
  for (int i = 0; i < 2000; ++i) {
    const std::string z = std::to_string(1 + i);
    obj += "v 0 0 " + z + "\nv 1 0 " + z + "\nv 0 1 " + z + "\n";
  }
  for (int i = 0; i < 2000; ++i)
    obj += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " +
           std::to_string(3 * i + 3) + "\n";
  rays.reserve(20'000'000);
  for (int i = 0; i < 1'000'000; ++i) rays += "0.2,0.2,0,0,0,1\n";
  test::write_file(dir + "/m.obj", obj);
  test::write_file(dir + "/r.csv", rays);
}

TEST(Interrupt, SigintWhileTracingRemovesTheTemporaryAndKeepsTheOldOutput) {
  const std::string dir = test::temp_dir("interrupt_hits");
  write_slow_hits_inputs(dir);
  test::write_file(dir + "/out.csv", "old\n");
  const pid_t pid = spawn_cli({"hits", "--accel", "brute", "--mesh", dir + "/m.obj", "--rays", dir + "/r.csv",
                               "-o", dir + "/out.csv"},
                              dir);
  ASSERT_TRUE(wait_until([&] { return has_temporary(dir, "out.csv"); })) << "no temporary appeared";
  EXPECT_EQ(interrupt(pid), 130) << test::read_file(dir + "/stderr");
  EXPECT_FALSE(has_temporary(dir, "out.csv"));
  EXPECT_EQ(test::read_file(dir + "/out.csv"), "old\n");
}

// Every signal whose default action ends the process: its temporary is removed too (a hang-up
// from a closed terminal, `timeout -s HUP`, Ctrl-\\, a pipe closed under us, ...).
TEST(Interrupt, EveryTerminatingSignalRemovesTheTemporary) {
  const std::string dir = test::temp_dir("interrupt_signals");
  write_slow_hits_inputs(dir);
  for (const int sig : {SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2}) {
    const pid_t pid = spawn_cli({"hits", "--accel", "brute", "--mesh", dir + "/m.obj", "--rays",
                                 dir + "/r.csv", "-o", dir + "/out.csv"},
                                dir);
    ASSERT_TRUE(wait_until([&] { return has_temporary(dir, "out.csv"); })) << "no temporary appeared";
    ::kill(pid, sig);
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 128 + sig) << strsignal(sig);
    EXPECT_FALSE(has_temporary(dir, "out.csv")) << strsignal(sig);
    EXPECT_FALSE(fs::exists(dir + "/out.csv")) << strsignal(sig);
  }
}

// A file size limit (ulimit -f) is a write error with a message, not a SIGXFSZ death that leaves
// the temporary.
TEST(Interrupt, FileSizeLimitIsAnErrorThatLeavesNothing) {
  const std::string dir = test::temp_dir("interrupt_fsize");
  std::string rays;
  for (int i = 0; i < 100'000; ++i) rays += "0.2,0.2,0,0,0,1\n";
  test::write_file(dir + "/m.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n");
  test::write_file(dir + "/r.csv", rays);
  const std::string cmd = "ulimit -f 64; '" + std::string(RAYVEC_CLI) + "' hits --mesh " + dir +
                          "/m.obj --rays " + dir + "/r.csv -o " + dir + "/out.csv 2>" + dir + "/stderr";
  const int raw = std::system(("bash -c \"" + cmd + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 1) << test::read_file(dir + "/stderr");
  EXPECT_NE(test::read_file(dir + "/stderr").find("cannot write " + dir + "/out.csv: File too large"),
            std::string::npos)
      << test::read_file(dir + "/stderr");
  EXPECT_FALSE(has_temporary(dir, "out.csv"));
  EXPECT_FALSE(fs::exists(dir + "/out.csv"));
}

TEST(Interrupt, SigintDuringARenderLeavesNoImage) {
  if (test::run_cli("render --help").out.find("Usage: rayvec render") == std::string::npos)
    GTEST_SKIP() << "no render command in this build";
  const std::string dir = test::temp_dir("interrupt_render");
  test::write_file(dir + "/m.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  test::write_file(dir + "/out.png", "old\n");
  // 512×512 pixels at 4096 samples each: minutes of work, interrupted once it has begun.
  const pid_t pid = spawn_cli({"render", dir + "/m.obj", "-o", dir + "/out.png", "--spp", "4096", "--width",
                               "512", "--height", "512"},
                              dir);
  ASSERT_TRUE(wait_until([&] {
    return test::read_file(dir + "/stdout").find("scene:") != std::string::npos;
  })) << test::read_file(dir + "/stderr");
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(interrupt(pid), 130) << test::read_file(dir + "/stderr");
  EXPECT_FALSE(has_temporary(dir, "out.png"));
  EXPECT_EQ(test::read_file(dir + "/out.png"), "old\n");
}

}  // namespace
}  // namespace rayvec
