#include "distributed/cluster.h"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "distributed/launcher.h"
#include "distributed/mpi_loader.h"
#include "io/error_report.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

MpiModule& mpi() {
  static MpiModule module;
  return module;
}

int env_rank(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : -1;
}

}  // namespace

Cluster& cluster() {
  static Cluster c;
  return c;
}

bool runs_across_ranks(int argc, char** argv) {
  std::vector<std::string> words;
  for (int i = 1; i < argc && words.size() < 2; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0 ||
        std::strcmp(argv[i], "--version") == 0)
      return true;  // rank 0 alone prints (the other ranks' stdout is closed)
    if (argv[i][0] != '-') words.emplace_back(argv[i]);
  }
  if (words.empty()) return true;
  const std::string& w = words[0];
  return w == "render" || w == "hits" || w == "visibility" ||
         (w == "bench" && words.size() > 1 && words[1] == "paper");
}

int Cluster::start() {
  const Launch launch = detect_launch();
  if (!launch.problem.empty()) {
    std::fprintf(stderr, "rayvec: %s\n", launch.problem.c_str());
    return 2;
  }
  if (!launch.launched) return 0;
  mpi() = load_mpi_module();
  if (!mpi().init) {
    if (launch.ranks <= 1) return 0;  // a one-rank launch runs as a plain process
    std::fprintf(stderr, "rayvec: launched as one of %d ranks (%s is set), but %s\n", launch.ranks,
                 launch.variable.c_str(), mpi().error.c_str());
    return 2;
  }
  char error[256] = "";
  if (!mpi().init(&rank_, &size_, error, sizeof error)) {
    std::fprintf(stderr, "rayvec: cannot start MPI: %s\n", error);
    return 1;
  }
  if (rank_ != 0) {
    // Rank 0 prints for all: the others' stdout and stderr are closed, and what they must say
    // (their failure, naming them) goes to the terminal they were started on.
    terminal_fd_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::close(null);
  }
  return 0;
}

void Cluster::say(const std::string& line) const {
  const std::string text = line + "\n";
  if (::write(terminal_fd_, text.data(), text.size()) < 0) return;
}

int Cluster::agree(int status) {
  agreed_ = true;
  if (!distributed()) return status;
  // The worst status wins; among ranks with it, the lowest reports.
  std::vector<int64_t> key{status > 0 ? (int64_t(status) << 32) | int64_t(size_ - 1 - rank_) : -1};
  mpi().allreduce(key.data(), 1, 0);
  if (key[0] < 0) return 0;
  const int worst = int(key[0] >> 32), reporter = size_ - 1 - int(key[0] & 0xffffffff);
  failure_agreed_ = true;
  if (reporter != 0) {
    // Rank 0 has printed its own message, if it failed; the reporter's reaches the terminal
    // through it.
    if (rank_ == reporter) {
      const std::string& m = last_error_message();
      send_vector(0, kTagAgreement, std::vector<char>(m.begin(), m.end()));
    } else if (root()) {
      const std::vector<char> m = recv_vector<char>(reporter, kTagAgreement);
      if (!m.empty()) std::fprintf(stderr, "%.*s\n", int(m.size()), m.data());
      std::fprintf(stderr, "rayvec: rank %d of %d stopped every rank (exit status %d)\n", reporter, size_,
                   worst);
    }
  }
  return worst;
}

void Cluster::begin_collective() {
  if (agreed_) return;
  if (const int status = agree(0); status != 0) throw ReportedFailure{status};
}

void Cluster::abort_job(int status) {
  std::string message = last_error_message();
  if (message.rfind("rayvec: ", 0) == 0) message.erase(0, 8);
  if (!root() && !message.empty())
    say("rayvec: rank " + std::to_string(rank_) + " of " + std::to_string(size_) + ": " + message);
  say("rayvec: rank " + std::to_string(rank_) + " of " + std::to_string(size_) + " failed (exit status " +
      std::to_string(status) + "); stopping every rank");
  if (!root()) ::dup2(terminal_fd_, 2);  // MPI_Abort's own notice needs a stderr
  mpi().abort(status);
  std::_Exit(status);
}

int Cluster::finish(int status) {
  if (!mpi().init || size_ == 0) return status;
  if (!agreed_)
    status = agree(status);
  else if (status != 0 && !failure_agreed_ && distributed())
    abort_job(status);
  mpi().finalize();
  return status;
}

void Cluster::test_failure_point() const {
  if (!distributed()) return;
  if (env_rank("RAYVEC_TEST_KILL_RANK") == rank_) std::raise(SIGKILL);
  if (env_rank("RAYVEC_TEST_FAIL_RANK") == rank_)
    throw RuntimeError("RAYVEC_TEST_FAIL_RANK: rank " + std::to_string(rank_) +
                       " fails on purpose (a test hook)");
}

void Cluster::broadcast(void* data, std::size_t bytes) {
  if (!distributed()) return;
  begin_collective();
  mpi().bcast(data, bytes, 0);
}

void Cluster::all_max(std::vector<int64_t>& values) {
  if (!distributed()) return;
  begin_collective();
  mpi().allreduce(values.data(), int(values.size()), 0);
}

void Cluster::all_sum(std::vector<int64_t>& values) {
  if (!distributed()) return;
  begin_collective();
  mpi().allreduce(values.data(), int(values.size()), 1);
}

void Cluster::send(int dest, int tag, const void* data, std::size_t bytes) {
  begin_collective();
  mpi().send(data, bytes, dest, tag);
}

int Cluster::recv(int source, int tag, void* data, std::size_t bytes) {
  begin_collective();
  return mpi().recv(data, bytes, source, tag);
}

bool Cluster::probe(int source, int tag, bool wait, int* from) {
  begin_collective();
  return mpi().probe(source, tag, wait ? 1 : 0, from) != 0;
}

}  // namespace rayvec
