// The kernel before the one-mask pre-test (commit c06ea87) compiled in its own namespace for A/B runs
// against today's (docs/benchmarks.md, "Brute-force kernel", row 11).
#include <cstdint>
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx512.h"
namespace rayvec::avx512 { namespace prev {
#include "prev_mt.inl"  // git show c06ea87:src/kernels/moller_trumbore.inl
const TriangleKernels kPrevMt = make_kernels<vfloat, Intersector::mt>(Isa::avx512);
} }
namespace rayvec { const TriangleKernels& variant_kernels() { return avx512::prev::kPrevMt; } }
