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

// The most threads --threads accepts. libgomp fails far above it (33000 threads: exit 1, its
// thread creation refused; 100000: SIGSEGV), and 1024 is well above the cores of any machine
// rayvec runs on, where more threads than cores only cost memory and switches.
constexpr int kMaxThreads = 1024;

// InputError unless 0 <= threads <= kMaxThreads (0: all cores).
void check_threads_option(int threads);

// Declares the options on `cmd`; with_accel adds --accel.
void add_trace_options(Command& cmd, TraceOptions& options, bool with_accel);

// Validates the values (InputError on a bad one, saying what is allowed), applies --threads to
// OpenMP and returns the configuration.
TraceConfig resolve_trace_options(const TraceOptions& options);

// The threads --threads asks for (all of OpenMP's when 0), for work done before
// resolve_trace_options applies it, such as loading the scene.
int requested_threads(const TraceOptions& options);
AccelKind resolve_accel(const TraceOptions& options);

}  // namespace rayvec
