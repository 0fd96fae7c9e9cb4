// Loads librayvec_mpi.so (distributed/mpi_module_abi.h) with dlopen: from RAYVEC_MPI_MODULE if set,
// else beside the rayvec binary, else in the build tree that made it.
#pragma once
#include <string>

#include "distributed/mpi_module_abi.h"

namespace rayvec {

struct MpiModule {
  RayvecMpiInitFn init = nullptr;
  RayvecMpiFinalizeFn finalize = nullptr;
  RayvecMpiAbortFn abort = nullptr;
  RayvecMpiAllreduceFn allreduce = nullptr;
  RayvecMpiBcastFn bcast = nullptr;
  RayvecMpiSendFn send = nullptr;
  RayvecMpiRecvFn recv = nullptr;
  RayvecMpiProbeFn probe = nullptr;
  std::string error;  // why it could not be loaded (then every pointer is null)
};

inline constexpr const char* kMpiModuleName = "librayvec_mpi.so";

MpiModule load_mpi_module();

}  // namespace rayvec
