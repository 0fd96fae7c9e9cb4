// rayvec: the command-line front end. Each subcommand lives in its own cmd_*.cpp and registers here.
#include <csignal>
#include <cstdlib>
#include <unistd.h>

#include "app/command_line.h"
#include "app/commands.h"
#include "io/atomic_file.h"

namespace {

// Ctrl-C: remove any output still being written (AtomicFile temporaries), then exit 130.
extern "C" void on_interrupt(int sig) {
  rayvec::remove_open_temporaries_on_signal();
  ::_exit(128 + sig);
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  rayvec::CommandLine cli("rayvec",
                          "rayvec: a SoA/SIMD Möller–Trumbore ray tracer.\n"
                          "Run `rayvec COMMAND --help` for each command's options and examples.");
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
  return cli.main(argc, argv);
}
