// Scalar lane type of the wide-BVH box tests (bvh/simd/box_lanes.inl): vfloat of the scalar ISA,
// one child at a time, for baseline x86-64 (no FMA: fmadd is a rounded multiply and a rounded add).
// Included only by *_scalar.cpp units; the box test body is compiled in namespace rayvec::scalar.
#pragma once
#include <utility>

#include "simd/vfloat_scalar.h"

namespace rayvec::scalar {

#include "bvh/simd/box_lanes.inl"

using BoxLanes4 = BoxLanes<vfloat, 4>;
using BoxLanes8 = BoxLanes<vfloat, 8>;

}  // namespace rayvec::scalar
