// The core clock, measured: a virtual machine often has no hardware performance counters and its
// frequency moves with the host's load, so tests per cycle — the unit the kernel is judged in — need
// a clock taken in the same run (see benchmarks.md#decision-clock-probes).
#pragma once

namespace rayvec {

// GHz of the calling thread's core: a chain of dependent one-cycle register-register integer adds
// (one add per cycle on every x86-64 core since the Pentium Pro) timed on the thread's CPU-time
// clock, so time the thread spends descheduled does not count. About 10 ms. Caveat: it measures
// the clock, not the share of the core — when a host hyperthread sibling competes for the vector
// units, a kernel gets fewer tests per measured cycle (benchmarks.md#decision-clock-probes).
double measure_clock_ghz();

// Seconds on the calling thread's CPU-time clock (CLOCK_THREAD_CPUTIME_ID).
double thread_cpu_seconds();

}  // namespace rayvec
