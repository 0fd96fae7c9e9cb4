// fma_rates() for avx512 (flags by file name, cmake/IsaFlags.cmake); the body is fma_rate.inl.
#include "bench/cpu_clock.h"
#include "bench/fma_rate.h"
#include "simd/vfloat_avx512.h"

namespace rayvec::avx512 {

#include "bench/fma_rate.inl"

}  // namespace rayvec::avx512
