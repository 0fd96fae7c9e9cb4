// `rayvec accuracy [--json] [-o docs/accuracy.md]`: every intersector × ISA over the hard-case
// families and a random control family, judged by the exact oracle, with throughput. The work is
// in src/accuracy/accuracy_report.cpp; this file parses options and writes the output.
#include <omp.h>

#include <cstdio>
#include <string>

#include "accuracy/accuracy_report.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "app/trace_options.h"
#include "io/atomic_file.h"
#include "io/input_error.h"

namespace rayvec {

namespace {

struct AccuracyArgs {
  bool json = false;
  std::string output;
  int threads = 0, scale = 2, size = 512, repeats = 3;
};

int run_accuracy(const AccuracyArgs& a) {
  if (a.scale < 1 || a.scale > 100) throw InputError("--scale: must be 1 to 100");
  if (a.size < 8 || a.size > 8192) throw InputError("--size: must be 8 to 8192");
  if (a.repeats < 1) throw InputError("--repeats: must be at least 1");
  check_threads_option(a.threads);
  if (a.threads > 0) omp_set_num_threads(a.threads);
  AccuracySettings settings;
  settings.scale = a.scale;
  settings.bvh_size = a.size;
  settings.repeats = a.repeats;
  const AccuracyReport report = measure_accuracy(settings, stderr);
  if (!a.output.empty()) {
    AtomicFile file(a.output);
    write_accuracy_markdown(report, file.stream());
    file.commit();
  }
  if (a.json)
    write_accuracy_json(report, stdout);
  else if (a.output.empty())
    write_accuracy_markdown(report, stdout);
  return 0;
}

}  // namespace

void register_accuracy_command(CommandLine& cli) {
  static AccuracyArgs a;
  cli.command("accuracy",
              "False misses, false hits and wrong-nearest rates of every intersector "
              "against an exact oracle, with throughput")
      .flag("--json", a.json, "print the results as JSON on stdout")
      .option("-o,--output", a.output, "write the markdown report to this file (e.g. docs/accuracy.md)")
      .option("--threads", a.threads, "OpenMP threads, 0 to 1024 (0: all cores)")
      .option("--scale", a.scale, "hard-case ray counts x scale (default 2)")
      .option("--size", a.size, "BVH primary rays: size x size pixels (default 512)")
      .option("--repeats", a.repeats, "timings: median of this many runs (default 3)")
      .footer(
          "Families and oracle: src/accuracy/hard_cases.h, src/accuracy/exact_oracle.h.\n"
          "Example: rayvec accuracy -o docs/accuracy.md --json > accuracy.json")
      .run([] { return run_accuracy(a); });
}

}  // namespace rayvec
