// Runs the rayvec binary under `mpirun -np 2 --oversubscribe` for the Mpi* tests (MPI build only).
#pragma once

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
  return run_launched(mpirun_prefix(ranks) + mpi_options + " ", args, stdin_text);
}

// The directory's entries, so a test can say that nothing (no image, no temporary) was left.
inline std::string entries_of(const std::string& dir) {
  std::string names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names += e.path().filename().string() + " ";
  return names;
}

}  // namespace rayvec::test
