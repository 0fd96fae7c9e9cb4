// The core clock, measured: this VM has no hardware performance counters (perf stat shows none) and
// its frequency moves with the host's load (3.5–3.8 GHz seen on the AMD EPYC of docs/benchmarks.md),
// so tests per cycle — the unit of issue 2's kernel target — need a clock taken in the same run.
#pragma once

namespace rayvec {

// GHz of the calling thread's core: a chain of dependent one-cycle register-register integer adds
// (one add per cycle on every x86-64 core since the Pentium Pro) timed on the thread's CPU-time
// clock, so time the thread spends descheduled does not count. About 10 ms. Caveat: it measures
// the clock, not the share of the core — when a host hyperthread sibling competes for the vector
// units, a kernel gets fewer tests per measured cycle (docs/benchmarks.md, "Brute-force kernel").
double measure_clock_ghz();

// Seconds on the calling thread's CPU-time clock (CLOCK_THREAD_CPUTIME_ID).
double thread_cpu_seconds();

}  // namespace rayvec
