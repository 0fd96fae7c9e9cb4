// Cluster: the ranks of a distributed run, as the commands see them. A process that no launcher
// started (distributed/launcher.h) is a cluster of one, and every operation is then a no-op or a
// copy; under mpirun every call goes to librayvec_mpi.so (distributed/mpi_module_abi.h). Calls are
// made from the main thread only.
//
// Failures. Until a command's first collective call the ranks work alone (parse options, load the
// scene, read inputs); that first call runs the agreement: every rank says how it fared, and when
// one failed, all stop with the worst exit status and the message is printed once (rank 0 prints
// it, naming the rank that found it when that was another). A rank that fails after the agreement
// ends the whole job (MPI_Abort), naming itself.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rayvec {

// Message tags of the distributed commands.
enum ClusterTag : int { kTagAgreement = 1, kTagTileRequest = 10, kTagTileReply, kTagResults = 20 };

class Cluster {
 public:
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  bool distributed() const { return size_ > 1; }

  // From rank 0 to every rank.
  void broadcast(void* data, std::size_t bytes);
  template <class T>
  void broadcast(std::vector<T>& v) {
    uint64_t n = v.size();
    broadcast(&n, sizeof n);
    v.resize(n);
    broadcast(v.data(), n * sizeof(T));
  }
  // Element-wise max (or sum) over every rank, in place.
  void all_max(std::vector<int64_t>& values);
  void all_sum(std::vector<int64_t>& values);
  // Point-to-point: send() blocks until the buffer may be reused; recv() until the message is
  // here (source: a rank or kAnySource) and returns its source. A vector goes as its size then its
  // contents.
  static constexpr int kAnySource = -1;
  void send(int dest, int tag, const void* data, std::size_t bytes);
  int recv(int source, int tag, void* data, std::size_t bytes);
  template <class T>
  void send_vector(int dest, int tag, const std::vector<T>& v) {
    const uint64_t n = v.size();
    send(dest, tag, &n, sizeof n);
    if (n) send(dest, tag, v.data(), n * sizeof(T));
  }
  template <class T>
  std::vector<T> recv_vector(int source, int tag) {
    uint64_t n = 0;
    const int from = recv(source, tag, &n, sizeof n);
    std::vector<T> v(n);
    if (n) recv(from, tag, v.data(), n * sizeof(T));
    return v;
  }
  // Whether a message is waiting (wait: block until one is); its source in *from.
  bool probe(int source, int tag, bool wait, int* from);

  // The agreement, if it has not run yet: returns when every rank is ready for collective work,
  // else throws ReportedFailure. Call it before work that cannot unwind (an OpenMP region) when
  // that work makes cluster calls.
  void begin_collective();

  // Test hooks, documented in docs/distributed.md#testing-failures: the rank named by
  // RAYVEC_TEST_KILL_RANK dies here (SIGKILL), the one named by RAYVEC_TEST_FAIL_RANK throws a
  // RuntimeError. Called once a rank has done some of its share of the work.
  void test_failure_point() const;

  // main(): start() before the command, finish() after it with its exit status; finish() returns
  // the process's exit status (or ends the job). start() returns 0, or an exit status after a
  // message (MPI missing where a launcher asked for it, a launch it cannot serve).
  int start();
  int finish(int status);

 private:
  int agree(int status);
  [[noreturn]] void abort_job(int status);
  void say(const std::string& line) const;  // to the terminal, whatever this rank's stderr is

  int rank_ = 0, size_ = 1;
  bool agreed_ = false, failure_agreed_ = false;
  int terminal_fd_ = 2;
};

// The process's cluster.
Cluster& cluster();

// The commands that run across ranks (render, hits, visibility, bench paper); any other under a
// launcher with more than one rank is refused (each rank would do it all).
bool runs_across_ranks(int argc, char** argv);

}  // namespace rayvec
