// Instantiates the ray–triangle kernels (moller_trumbore.inl) for scalar. Thin on purpose: the
// kernel body is shared; only the vector type and the compile flags (cmake/IsaFlags.cmake) differ.
#include <cstdint>

#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_scalar.h"

namespace rayvec::scalar {

#include "kernels/moller_trumbore.inl"
#include "kernels/watertight.inl"

namespace {
// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const TriangleKernels kPaper = make_kernels<vfloat, Intersector::paper>(Isa::scalar);
constinit const TriangleKernels kMt = make_kernels<vfloat, Intersector::mt>(Isa::scalar);
constinit const TriangleKernels kMt64 = make_kernels<vdouble, Intersector::mt64>(Isa::scalar);
constinit const TriangleKernels kWatertight =
    make_watertight_kernels<vfloat, Intersector::watertight>(Isa::scalar);
constinit const TriangleKernels kWatertight64 =
    make_watertight_kernels<vdouble, Intersector::watertight64>(Isa::scalar);
}  // namespace

const TriangleKernels& triangle_kernels(Intersector intersector) {
  switch (intersector) {
    case Intersector::paper: return kPaper;
    case Intersector::mt64: return kMt64;
    case Intersector::watertight: return kWatertight;
    case Intersector::watertight64: return kWatertight64;
    case Intersector::mt: break;
  }
  return kMt;
}

}  // namespace rayvec::scalar
