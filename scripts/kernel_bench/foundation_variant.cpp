// The foundation kernel (commit 7311440) compiled in its own namespace for A/B runs.
#include <cstdint>
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx512.h"
namespace rayvec::avx512 { namespace old {
#include "foundation_mt.inl"  // git show 7311440:src/kernels/moller_trumbore.inl
const TriangleKernels kOldMt = make_kernels<vfloat, Intersector::mt>(Isa::avx512);
} }
namespace rayvec { const TriangleKernels& variant_kernels() { return avx512::old::kOldMt; } }
