// The C interface of librayvec_mpi.so, the module that holds every MPI call. rayvec loads it with
// dlopen only when a launcher (mpirun, srun) started the process, so a plain `rayvec` pays nothing
// for OpenMPI's shared libraries and MPI_Init (docs/distributed.md#start-up). Plain C types only:
// the module and the binary share no C++ objects. Every call is made from the main thread only
// (MPI_THREAD_FUNNELED); an MPI error ends the whole job (MPI_ERRORS_ARE_FATAL).
#pragma once
#include <cstddef>
#include <cstdint>

extern "C" {

// Bumped whenever a signature below changes; the loader refuses a module of another version.
constexpr int kRayvecMpiAbi = 1;

// Any source, for recv and probe.
constexpr int kRayvecMpiAnySource = -1;

using RayvecMpiAbiFn = int (*)();
// MPI_Init_thread(FUNNELED) on the world communicator; 0 with `error` filled on failure.
using RayvecMpiInitFn = int (*)(int* rank, int* size, char* error, std::size_t error_size);
using RayvecMpiFinalizeFn = void (*)();
// MPI_Abort(MPI_COMM_WORLD, status): ends every rank; does not return.
using RayvecMpiAbortFn = void (*)(int status);
// In place over all ranks: op 0 = max, 1 = sum.
using RayvecMpiAllreduceFn = void (*)(int64_t* values, int count, int op);
// `bytes` bytes from `root` to every rank.
using RayvecMpiBcastFn = void (*)(void* data, std::size_t bytes, int root);
// Blocking point-to-point byte messages (any size: sent in pieces below MPI's int count limit).
using RayvecMpiSendFn = void (*)(const void* data, std::size_t bytes, int dest, int tag);
// Receives one message sent by one send call; returns its source rank. `bytes` must be its size.
using RayvecMpiRecvFn = int (*)(void* data, std::size_t bytes, int source, int tag);
// Whether a message with `tag` from `source` is waiting (without blocking unless `wait`); its
// source in *found_source.
using RayvecMpiProbeFn = int (*)(int source, int tag, int wait, int* found_source);
}
