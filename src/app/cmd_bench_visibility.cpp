// `rayvec bench visibility`: the CUDA visibility study's table (bench/visibility_bench.h).
#include <charconv>
#include <cstdio>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/trace_options.h"
#include "bench/visibility_bench.h"
#include "gpu/math_dispatch.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

// "A,B,C": integers in [lo, hi]; InputError naming the option otherwise.
std::vector<int> parse_list(const std::string& option, const std::string& text, int lo, int hi) {
  std::vector<int> out;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t comma = text.find(',', pos);
    if (comma == std::string::npos) comma = text.size();
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data() + pos, text.data() + comma, v);
    if (ec != std::errc() || end != text.data() + comma || v < lo || v > hi)
      throw InputError(option + ": '" + text + "' is not a comma-separated list of integers from " +
                       std::to_string(lo) + " to " + std::to_string(hi));
    out.push_back(v);
    pos = comma + 1;
  }
  return out;
}

}  // namespace

void register_bench_visibility_command(Command& bench) {
  struct Options {
    std::string rings = "100,200", tiles = "64,128,256,512,1024", intersector = "mt";
    int threads = 0;
    double cpu_budget = 4e9;
    bool no_gpu = false;
  };
  static Options o;
  bench
      .subcommand(
          "visibility",
          "The CUDA visibility study's table: CPU sequential, rayvec CPU per ISA and threads, GPU kernels")
      .option("--rings", o.rings,
              "sphere sizes, as rings (100 = the study's 19,802 vertices x 39,600 triangles)")
      .option("--tiles", o.tiles, "shared-memory tile sizes of the GPU rows (64 to 1024 triangles)")
      .option("--threads", o.threads, "most CPU threads (rows at 1, 2, 4, ... and this; 0 = all cores)")
      .option("--cpu-budget", o.cpu_budget, "skip a brute-force CPU row above this many tests per thread")
      .option("--intersector", o.intersector, "mt (default), mt64, watertight or watertight64")
      .flag("--no-gpu", o.no_gpu, "CPU rows only")
      .footer(
          "For each size: the vertices of a closed bumpy sphere, seen from 0,0,-3 (is the open segment\n"
          "to each vertex blocked?), traced brute force as the study did: the scalar kernel on one thread\n"
          "(its sequential row), every ISA of this CPU on 1, 2, 4, ... threads, the BVH for scale, and on\n"
          "a CUDA GPU the global kernel, the shared tiles and the SoA tiles per tile size (kernel time:\n"
          "median of 3 after a warm-up; the ray upload and result download apart). Every row's answers\n"
          "are checked against the BVH's; exit 1 if one differs. Without a GPU its rows say why.\n"
          "Mtests/s = vertices x triangles / seconds (the brute-force work, also for the BVH row).\n"
          "Example (the study's size only, a quick look):\n"
          "  rayvec bench visibility --rings 100 --tiles 256")
      .run([] {
        VisibilityBenchOptions v;
        v.rings = parse_list("--rings", o.rings, 3, 2000);
        v.tiles = parse_list("--tiles", o.tiles, 64, 1024);
        check_threads_option(o.threads);
        v.max_threads = o.threads;
        if (!(o.cpu_budget > 0)) throw InputError("--cpu-budget: must be a positive number of tests");
        v.cpu_budget = o.cpu_budget;
        const auto i = parse_intersector(o.intersector);
        if (!i || !gpu::device_supports(*i))
          throw InputError("--intersector: '" + o.intersector +
                           "' (choose mt, mt64, watertight or watertight64)");
        v.intersector = *i;
        v.gpu = !o.no_gpu;
        return run_visibility_bench(v, stdout) == 0 ? 0 : 1;
      });
}

}  // namespace rayvec
