#include "bench/fma_rate.h"

#include <algorithm>

#include "bench/cpu_clock.h"

namespace rayvec {
namespace {

// Scalar: twelve chains of float a·m + c. With -ffp-contract=fast (g++'s default outside ISO
// mode) and no FMA in baseline x86-64, this is a multiply and an add per chain step: the number
// is "scalar FMA-equivalents", comparable only with itself.
double scalar_fma_per_ns() {
  constexpr long kIterations = 200'000;
  volatile float mv = 0.999999f, cv = 1e-6f;
  const float m = mv, c = cv;
  constexpr int kRounds = 31;
  double rates[kRounds];
  float sink = 0;
  for (int round = 0; round < kRounds; ++round) {
    float a[12];
    for (int k = 0; k < 12; ++k) a[k] = 1.0f + 0.1f * float(k);
    const double start = thread_cpu_seconds();
    for (long i = 0; i < kIterations; ++i)
      for (float& x : a) x = x * m + c;
    const double seconds = thread_cpu_seconds() - start;
    for (float x : a) sink += x;
    rates[round] = seconds > 0 ? double(kIterations) * 12.0 / seconds * 1e-9 : 0.0;
  }
  std::nth_element(rates, rates + kRounds / 2, rates + kRounds);
  return sink == 12345.0f ? rates[kRounds / 2] + 1e-9 : rates[kRounds / 2];
}

}  // namespace

double measure_fma_per_ns(Isa isa) {
  if (!isa_supported(isa)) return 0;
  switch (isa) {
    case Isa::avx512: return avx512::fma_per_ns();
    case Isa::avx2: return avx2::fma_per_ns();
    default: return scalar_fma_per_ns();
  }
}

}  // namespace rayvec
