#include "app/trace_options.h"

#include <omp.h>

#include "app/command_line.h"
#include "io/input_error.h"

namespace rayvec {

void add_trace_options(Command& cmd, TraceOptions& options, bool with_accel) {
  cmd.option("--isa", options.isa, "SIMD instruction set: auto (best this CPU has), scalar, avx2 or avx512")
      .option("--intersector", options.intersector,
              "ray-triangle arithmetic: mt (float, no epsilon), mt64 (double), paper "
              "(Sena et al. 2018: |det| < 1e-6 culled, t > 1e-6), watertight (Woop et al. 2013: no ray "
              "slips between triangles of a closed mesh), watertight64 (the same in double)")
      .option("--threads", options.threads,
              "threads for tracing (OpenMP) and, with 2 or more, for reading an OBJ of 16 MiB and up; 0 to "
              "1024 (0 = all cores)");
  if (with_accel)
    cmd.option("--accel", options.accel,
               "acceleration structure: bvh (default; wide SAH BVH) or brute (every triangle, the "
               "paper's workload); both return the same hits");
}

void check_threads_option(int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw InputError("--threads: must be between 0 (all cores) and " + std::to_string(kMaxThreads) +
                     ", got " + std::to_string(threads));
}

TraceConfig resolve_trace_options(const TraceOptions& options) {
  TraceConfig config;
  if (const std::string err = resolve_isa(options.isa, config.isa); !err.empty())
    throw InputError("--isa: " + err);
  const auto intersector = parse_intersector(options.intersector);
  if (!intersector)
    throw InputError("--intersector: unknown '" + options.intersector +
                     "' (choose mt, mt64, paper, watertight or watertight64)");
  config.intersector = *intersector;
  check_threads_option(options.threads);
  if (options.threads > 0) omp_set_num_threads(options.threads);
  return config;
}

int requested_threads(const TraceOptions& options) {
  return options.threads > 0 ? options.threads : omp_get_max_threads();
}

AccelKind resolve_accel(const TraceOptions& options) {
  const auto kind = parse_accel(options.accel);
  if (!kind) throw InputError("--accel: unknown '" + options.accel + "' (choose brute or bvh)");
  return *kind;
}

}  // namespace rayvec
