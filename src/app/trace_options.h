// The options every tracing command shares: --isa, --intersector, --threads, --accel.
#pragma once
#include <string>

#include "accel/accelerator.h"

namespace rayvec {

class Command;

struct TraceOptions {
  std::string isa = "auto";
  std::string intersector = "mt";
  std::string accel = "bvh";  // brute stays available for the paper's workload
  int threads = 0;            // 0: all cores
};

// Declares the options on `cmd`; with_accel adds --accel.
void add_trace_options(Command& cmd, TraceOptions& options, bool with_accel);

// Validates the values (InputError on a bad one, saying what is allowed), applies --threads to
// OpenMP and returns the configuration.
TraceConfig resolve_trace_options(const TraceOptions& options);
AccelKind resolve_accel(const TraceOptions& options);

}  // namespace rayvec
