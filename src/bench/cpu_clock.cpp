#include "bench/cpu_clock.h"

#include <time.h>

namespace rayvec {

double thread_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double measure_clock_ghz() {
  // 16 dependent adds per iteration: the loop's own dec/jnz run in parallel with the chain, so the
  // chain's latency (1 cycle per add) is the only bound. Written in asm so no compiler folds it.
  // Register + register: recent Intel cores fold chains of add-immediate at rename (16 `add $1`
  // can retire in a few cycles and read several times the real clock); a register operand has to
  // go through the adder (benchmarks.md#decision-clock-probes).
  constexpr long kIterations = 2'500'000;  // 40 M adds ≈ 10 ms at 4 GHz
  long x = 0, i = kIterations;
  const long one = 1;
  const double start = thread_cpu_seconds();
  __asm__ volatile("1:\n .rept 16\n add %2, %0\n .endr\n dec %1\n jnz 1b\n" : "+r"(x), "+r"(i) : "r"(one));
  const double seconds = thread_cpu_seconds() - start;
  return seconds > 0 ? double(kIterations) * 16.0 / seconds / 1e9 : 0.0;
}

}  // namespace rayvec
