// librayvec_mpi.so: the only file that includes <mpi.h> (see mpi_module_abi.h for why it is a module).
#include <mpi.h>

#include <algorithm>
#include <cstdio>

#include "distributed/mpi_module_abi.h"

namespace {

// MPI counts are ints: larger transfers go in pieces of at most 1 GiB.
constexpr std::size_t kPiece = std::size_t(1) << 30;

int source_of(int source) { return source == kRayvecMpiAnySource ? MPI_ANY_SOURCE : source; }

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int rayvec_mpi_abi() { return kRayvecMpiAbi; }

__attribute__((visibility("default"))) int rayvec_mpi_init(int* rank, int* size, char* error,
                                                           std::size_t error_size) {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::snprintf(error, error_size, "MPI_Init_thread failed");
    return 0;
  }
  if (provided < MPI_THREAD_FUNNELED) {
    std::snprintf(error, error_size, "the MPI library does not offer MPI_THREAD_FUNNELED");
    return 0;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
  return 1;
}

__attribute__((visibility("default"))) void rayvec_mpi_finalize() { MPI_Finalize(); }

__attribute__((visibility("default"))) void rayvec_mpi_abort(int status) {
  MPI_Abort(MPI_COMM_WORLD, status);
}

__attribute__((visibility("default"))) void rayvec_mpi_allreduce(int64_t* values, int count, int op) {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_INT64_T, op == 0 ? MPI_MAX : MPI_SUM, MPI_COMM_WORLD);
}

__attribute__((visibility("default"))) void rayvec_mpi_bcast(void* data, std::size_t bytes, int root) {
  for (std::size_t at = 0; at < bytes; at += kPiece)
    MPI_Bcast(static_cast<char*>(data) + at, int(std::min(kPiece, bytes - at)), MPI_BYTE, root,
              MPI_COMM_WORLD);
}

__attribute__((visibility("default"))) void rayvec_mpi_send(const void* data, std::size_t bytes, int dest,
                                                            int tag) {
  std::size_t at = 0;
  do {
    const std::size_t n = std::min(kPiece, bytes - at);
    MPI_Send(static_cast<const char*>(data) + at, int(n), MPI_BYTE, dest, tag, MPI_COMM_WORLD);
    at += n;
  } while (at < bytes);
}

__attribute__((visibility("default"))) int rayvec_mpi_recv(void* data, std::size_t bytes, int source,
                                                           int tag) {
  // The first piece fixes the source: the rest of the message comes from the same rank, in order.
  MPI_Status status;
  std::size_t at = 0;
  int from = source_of(source);
  do {
    const std::size_t n = std::min(kPiece, bytes - at);
    MPI_Recv(static_cast<char*>(data) + at, int(n), MPI_BYTE, from, tag, MPI_COMM_WORLD, &status);
    from = status.MPI_SOURCE;
    at += n;
  } while (at < bytes);
  return from;
}

__attribute__((visibility("default"))) int rayvec_mpi_probe(int source, int tag, int wait,
                                                            int* found_source) {
  MPI_Status status;
  int found = 1;
  if (wait)
    MPI_Probe(source_of(source), tag, MPI_COMM_WORLD, &status);
  else
    MPI_Iprobe(source_of(source), tag, MPI_COMM_WORLD, &found, &status);
  if (found) *found_source = status.MPI_SOURCE;
  return found;
}
}
