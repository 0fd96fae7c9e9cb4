// Whether an MPI launcher started this process, read from the environment it sets before exec: a
// plain `rayvec` never loads MPI (whose libraries and MPI_Init cost every command start-up time,
// docs/distributed.md#start-up), and `mpirun -np N rayvec` / `srun --mpi=pmix rayvec` always do.
#pragma once
#include <functional>
#include <string>

namespace rayvec {

struct Launch {
  bool launched = false;  // a launcher variable is set: initialise MPI
  int ranks = 0;          // the job size the launcher announced (0 = not said)
  std::string variable;   // the variable that told (for messages)
  std::string problem;    // non-empty: a launch rayvec cannot serve (exit 2 with this text)
};

// `getenv` looks one variable up (null when unset); the default reads the process environment.
// Launched when OMPI_COMM_WORLD_SIZE (OpenMPI's mpirun), PMIX_RANK (PMIx launchers, srun
// --mpi=pmix), PMI_RANK or PMI_SIZE (MPICH's hydra, srun --mpi=pmi2) is set. srun without an MPI
// plugin sets only SLURM_* variables: with more than one task that is a problem (every task would
// render the whole image alone), not a launch.
Launch detect_launch(const std::function<const char*(const char*)>& getenv);
Launch detect_launch();

}  // namespace rayvec
