#include "distributed/launcher.h"

#include <cstdlib>

namespace rayvec {
namespace {

int positive_int(const char* text) {
  if (!text || !*text) return 0;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  return *end == '\0' && v > 0 && v < (1L << 30) ? int(v) : 0;
}

}  // namespace

Launch detect_launch(const std::function<const char*(const char*)>& getenv) {
  Launch l;
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (!getenv(name)) continue;
    l.launched = true;
    l.variable = name;
    break;
  }
  if (l.launched) {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS", "SLURM_NTASKS"})
      if (const int n = positive_int(getenv(name))) {
        l.ranks = n;
        break;
      }
    return l;
  }
  if (const int n = positive_int(getenv("SLURM_STEP_NUM_TASKS")); n > 1 && getenv("SLURM_STEP_ID"))
    l.problem = "srun started " + std::to_string(n) +
                " tasks without an MPI plugin, so each would do the whole job alone: run `srun --mpi=pmix "
                "rayvec ...` (see `srun --mpi=list`), or one task";
  return l;
}

Launch detect_launch() {
  return detect_launch([](const char* name) { return static_cast<const char*>(std::getenv(name)); });
}

}  // namespace rayvec
