// Runs the rayvec binary under `mpirun -np 2 --oversubscribe` for the Mpi* tests (MPI build only).
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_support.h"

namespace rayvec::test {

inline std::string mpirun_prefix(int ranks = 2) {
  // As root, OpenMPI refuses to start without these; --oversubscribe: more ranks than cores is fine.
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  return std::string("'") + RAYVEC_MPIEXEC + "' -np " + std::to_string(ranks) + " --oversubscribe ";
}

// `mpirun -np RANKS --oversubscribe [MPI_OPTIONS] rayvec ARGS`; MPI_OPTIONS e.g. "-x NAME=value".
inline CommandResult run_mpi(const std::string& args, const std::string& mpi_options = "",
                             const std::string& stdin_text = "", int ranks = 2) {
  const std::string dir = temp_dir("mpi_cli");
  const std::string in = dir + "/stdin", out = dir + "/stdout", err = dir + "/stderr";
  write_file(in, stdin_text);
  const std::string cmd = mpirun_prefix(ranks) + mpi_options + " '" + RAYVEC_CLI + "' " + args + " <'" + in +
                          "' >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove_all(dir);
  return r;
}

// How many times `needle` occurs in `text`.
inline int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// The directory's entries, so a test can say that nothing (no image, no temporary) was left.
inline std::string entries_of(const std::string& dir) {
  std::string names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names += e.path().filename().string() + " ";
  return names;
}

}  // namespace rayvec::test
