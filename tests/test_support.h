// Helpers shared by the tests.
#pragma once
#include <string>

namespace rayvec::test {

struct CommandResult {
  int status = -1;  // exit status
  std::string out, err;
};

// Runs the rayvec binary with `args` (a shell-quoted string) and captures stdout and stderr.
CommandResult run_cli(const std::string& args, const std::string& stdin_text = "");

// The same behind a launcher (e.g. "mpirun -np 2 "; empty: none).
CommandResult run_launched(const std::string& launcher, const std::string& args,
                           const std::string& stdin_text);

// How many times `needle` occurs in `text`.
int count_of(const std::string& text, const std::string& needle);

// A fresh empty directory in the system's temp area, removed with its contents when the test
// process exits (kept if RAYVEC_KEEP_TEST_FILES is set).
std::string temp_dir(const std::string& name);

std::string read_file(const std::string& path);
void write_file(const std::string& path, const std::string& text);

}  // namespace rayvec::test
