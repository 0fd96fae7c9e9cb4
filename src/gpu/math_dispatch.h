// The intersectors the device math provides, and the one switch from the run-time Intersector to
// the compile-time math type (mt_math.h, watertight_math.h). `paper` stays CPU-only: its absolute
// epsilons exist to reproduce one paper's table, not to be ported.
#pragma once
#include "gpu/mt_math.h"
#include "gpu/watertight_math.h"
#include "kernels/intersector.h"

namespace rayvec::gpu {

inline constexpr bool device_supports(Intersector i) { return i != Intersector::paper; }

// Calls f(Math{}) for the intersector's math; false (and no call) for an unsupported one.
template <bool Fused, class F>
bool visit_math(Intersector i, F&& f) {
  switch (i) {
    case Intersector::mt: f(MtFloat<Fused>{}); return true;
    case Intersector::mt64: f(MtDouble<Fused>{}); return true;
    case Intersector::watertight: f(WatertightMath<float>{}); return true;
    case Intersector::watertight64: f(WatertightMath<double>{}); return true;
    case Intersector::paper: return false;
  }
  return false;
}

}  // namespace rayvec::gpu
