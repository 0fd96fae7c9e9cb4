#include "bench/fma_rate.h"

#include <vector>

#include "bench/median.h"

namespace rayvec {

double measure_fma_per_ns(Isa isa) {
  if (!isa_supported(isa)) return 0;
  double rates[kFmaRounds];
  switch (isa) {
    case Isa::avx512: avx512::fma_rates(rates); break;
    case Isa::avx2: avx2::fma_rates(rates); break;
    default: scalar::fma_rates(rates); break;
  }
  // the median round, like the clock's one long run an average rate (the best round would sit
  // above it and put FMA/cycle over the pipes' count)
  return median(std::vector<double>(rates, rates + kFmaRounds));
}

}  // namespace rayvec
