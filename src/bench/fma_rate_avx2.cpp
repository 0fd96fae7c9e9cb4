// fma_rates() for avx2 (flags by file name, cmake/IsaFlags.cmake); the body is fma_rate.inl.
#include "bench/cpu_clock.h"
#include "bench/fma_rate.h"
#include "simd/vfloat_avx2.h"

namespace rayvec::avx2 {

#include "bench/fma_rate.inl"

}  // namespace rayvec::avx2
