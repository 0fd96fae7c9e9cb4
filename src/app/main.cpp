// rayvec: the command-line front end. Each subcommand lives in its own cmd_*.cpp and registers here.
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <cstdlib>
#include <unistd.h>

#include "app/command_line.h"
#include "app/commands.h"
#include "distributed/cluster.h"
#include "io/atomic_file.h"
#include "io/error_report.h"
#include "io/input_error.h"
#include "io/text_file.h"

namespace {

// Ctrl-C and every other signal whose default action ends the process: remove any output still
// being written (AtomicFile temporaries), then exit 128 + the signal (130 for SIGINT).
extern "C" void on_interrupt(int sig) {
  rayvec::remove_open_temporaries_on_signal();
  ::_exit(128 + sig);
}

void install_signal_handlers() {
  // SIGPIPE included: a reader that goes away (`rayvec ... | head`) ends rayvec as it ends any
  // filter, but without leaving a temporary behind.
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2})
    std::signal(sig, on_interrupt);
  // A file size limit (ulimit -f) makes write() fail with EFBIG instead: the output's own error
  // path then says "File too large" and removes the temporary.
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace

int main(int argc, char** argv) {
  // Under mpirun or srun: MPI starts here (and only then, distributed/launcher.h); after it, so
  // that the handlers are ours.
  rayvec::Cluster& cluster = rayvec::cluster();
  if (const int status = cluster.start(); status != 0) return status;
  install_signal_handlers();
  if (cluster.distributed() && !rayvec::runs_across_ranks(argc, argv)) {
    rayvec::report_error(
        "rayvec: this command does not run across ranks (render, hits, visibility and bench paper do): "
        "run it without mpirun/srun");
    return cluster.finish(2);
  }
  rayvec::CommandLine cli("rayvec",
                          "rayvec: a SoA/SIMD Möller–Trumbore ray tracer.\n"
                          "Run `rayvec COMMAND --help` for each command's options and examples.");
  // A malformed input limit stops every command that reads input before it starts; help and
  // `info` (which shows the limit and the problem) still run.
  cli.check_before_input([] {
    if (const auto problem = rayvec::input_limit_problem()) throw rayvec::InputError(*problem);
  });
  rayvec::register_info_command(cli);
  rayvec::register_hits_command(cli);
  rayvec::register_visibility_command(cli);
  rayvec::register_compare_command(cli);
  rayvec::register_render_command(cli);
  rayvec::register_trace_command(cli);
  rayvec::register_accuracy_command(cli);
  rayvec::Command& bench =
      cli.command("bench", "Benchmarks: print rays/s or tests/s with CPU, ISA and threads");
  // bench subcommands register on it: register_bench_<name>_command(bench)
  rayvec::register_bench_paper_command(bench);
  rayvec::register_bench_rays_command(bench);
  rayvec::register_bench_obj_command(bench);
  rayvec::register_bench_visibility_command(bench);
  int status = cli.main(argc, argv);
  // Every command's output (and --help) ends here: a full disk or a closed pipe found only at the
  // final flush must not pass for success (`rayvec info > /dev/full`).
  std::cout.flush();
  if ((std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) && status == 0) {
    std::fprintf(stderr, "rayvec: cannot write standard output: %s\n", std::strerror(errno ? errno : EIO));
    status = 1;
  }
  return cluster.finish(status);
}
