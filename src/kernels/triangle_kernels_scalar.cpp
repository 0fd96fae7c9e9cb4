// Instantiates the ray–triangle kernels for scalar. Thin on purpose: the kernel bodies
// (moller_trumbore.inl, mt_float.inl, mt_float_rays.inl, mt_float_groups.inl, watertight.inl) and
// the tables (triangle_kernel_tables.inl) are shared; only the vector types and the compile flags
// (cmake/IsaFlags.cmake) differ.
#include <cstdint>

#include "kernels/triangle_kernels.h"
#include "simd/vfloat_scalar.h"

namespace rayvec::scalar {

constexpr Isa kThisIsa = Isa::scalar;

#include "kernels/moller_trumbore.inl"
#include "kernels/mt_float.inl"
#include "kernels/mt_float_rays.inl"
#include "kernels/mt_float_groups.inl"
#include "kernels/watertight.inl"
#include "kernels/triangle_kernel_tables.inl"

}  // namespace rayvec::scalar
