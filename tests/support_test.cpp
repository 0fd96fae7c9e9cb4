// test_support.h helpers (this file also holds their definitions, so every test part can use them).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "test_support.h"

namespace rayvec::test {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

namespace {

// The directories temp_dir made in this process, removed when it exits (ctest runs every test in
// a process of its own), unless RAYVEC_KEEP_TEST_FILES is set, to look at them after a failure.
class TempDirs {
 public:
  ~TempDirs() {
    if (std::getenv("RAYVEC_KEEP_TEST_FILES") != nullptr) return;
    std::error_code ignored;
    for (const auto& dir : dirs_) std::filesystem::remove_all(dir, ignored);
  }
  void add(const std::filesystem::path& dir) { dirs_.push_back(dir); }

 private:
  std::vector<std::filesystem::path> dirs_;
};

TempDirs made_dirs;

}  // namespace

std::string temp_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("rayvec_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  made_dirs.add(dir);
  return dir.string();
}

CommandResult run_launched(const std::string& launcher, const std::string& args,
                           const std::string& stdin_text) {
  const std::string dir = temp_dir("cli");
  const std::string in = dir + "/stdin", out = dir + "/stdout", err = dir + "/stderr";
  write_file(in, stdin_text);
  const std::string cmd =
      launcher + "'" + RAYVEC_CLI + "' " + args + " <'" + in + "' >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove_all(dir);
  return r;
}

CommandResult run_cli(const std::string& args, const std::string& stdin_text) {
  return run_launched("", args, stdin_text);
}

int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

TEST(TestSupport, RunsTheCli) {
  const CommandResult r = run_cli("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("rayvec"), std::string::npos);
}

}  // namespace rayvec::test
