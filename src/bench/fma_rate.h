// The vector throughput this thread gets, measured. On a shared virtual machine the brute-force
// kernel can run markedly slower for seconds at a time while the clock (cpu_clock.h, a latency
// chain) barely moves. A latency chain cannot see a neighbour sharing the vector pipes; a
// throughput loop can. So `bench paper` measures both and prints FMAs per cycle next to the
// kernel's tests per cycle: about 2 on an uncontended core with two FMA pipes, less while the pipes
// are shared — or, for 512-bit vectors only, on a core that executes them as two 256-bit halves
// (then the AVX2 probe still reads 2). A slow run with FMA/c still at 2 was slowed by something
// else — caches or memory, not the pipes (benchmarks.md#decision-clock-probes).
#pragma once

#include "platform/isa.h"

namespace rayvec {

// Vector FMAs per nanosecond of thread CPU time at `isa`'s width (16 floats for avx512, 8 for
// avx2; scalar: one float FMA written as a*b+c), from 12 independent accumulator chains — enough
// to fill two pipes of 4-cycle latency — over about 10 ms. Divide by measure_clock_ghz() for FMAs
// per cycle. 0 if the ISA is not supported by this CPU.
double measure_fma_per_ns(Isa isa);

// Each ISA unit's probe: the vector FMAs per nanosecond of each of kFmaRounds rounds (about 0.3 ms
// each), into rates[0..kFmaRounds). measure_fma_per_ns keeps their median; the selection runs in
// the baseline unit, not in an ISA unit (whose out-of-line std:: code could be picked by the linker
// for baseline callers).
inline constexpr int kFmaRounds = 31;
namespace scalar {
void fma_rates(double* rates);  // a·m + c as a multiply and an add (no FMA in baseline x86-64)
}
namespace avx2 {
void fma_rates(double* rates);
}
namespace avx512 {
void fma_rates(double* rates);
}

}  // namespace rayvec
