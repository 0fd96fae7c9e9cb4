// The function tables of one ISA unit: every intersector instantiated over that unit's vector types.
// Included last by triangle_kernels_<isa>.cpp, inside namespace rayvec::<isa>, after it defines
// kThisIsa and includes the kernel bodies (moller_trumbore.inl, mt_float.inl, mt_float_rays.inl,
// mt_float_groups.inl, watertight.inl).

namespace {
// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const TriangleKernels kPaper = make_kernels<vfloat, Intersector::paper>(kThisIsa);
constinit const TriangleKernels kMt = make_kernels<vfloat, Intersector::mt>(kThisIsa);
constinit const TriangleKernels kMtOrdered =
    make_kernels<vfloat, Intersector::mt, MtPretest::ordered_compares>(kThisIsa);
constinit const TriangleKernels kMt64 = make_kernels<vdouble, Intersector::mt64>(kThisIsa);
constinit const TriangleKernels kWatertight =
    make_watertight_kernels<vfloat, Intersector::watertight>(kThisIsa);
constinit const TriangleKernels kWatertight64 =
    make_watertight_kernels<vdouble, Intersector::watertight64>(kThisIsa);
}  // namespace

const TriangleKernels& triangle_kernels(Intersector intersector, MtPretest pretest) {
  switch (intersector) {
    case Intersector::paper: return kPaper;
    case Intersector::mt64: return kMt64;
    case Intersector::watertight: return kWatertight;
    case Intersector::watertight64: return kWatertight64;
    case Intersector::mt: break;
  }
  return pretest == MtPretest::ordered_compares ? kMtOrdered : kMt;
}
