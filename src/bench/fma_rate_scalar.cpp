// fma_rates() for scalar (baseline flags: a·m + c is a multiply and an add); the body is fma_rate.inl.
#include "bench/cpu_clock.h"
#include "bench/fma_rate.h"
#include "simd/vfloat_scalar.h"

namespace rayvec::scalar {

#include "bench/fma_rate.inl"

}  // namespace rayvec::scalar
