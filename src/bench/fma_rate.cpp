#include "bench/fma_rate.h"

namespace rayvec {

double measure_fma_per_ns(Isa isa) {
  if (!isa_supported(isa)) return 0;
  switch (isa) {
    case Isa::avx512: return avx512::fma_per_ns();
    case Isa::avx2: return avx2::fma_per_ns();
    default: return scalar::fma_per_ns();
  }
}

}  // namespace rayvec
