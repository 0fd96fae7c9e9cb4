// AVX2 lane types of the wide-BVH box tests (bvh/simd/box_lanes.inl): vfloat, one ymm of 8 floats
// per bounds row. BoxLanes8 tests a WideNode<8> (one register per row), BoxLanes16 a WideNode<16>
// (two). Included only by *_avx2.cpp units; the box test body is compiled in namespace rayvec::avx2.
#pragma once
#include <utility>

#include "simd/vfloat_avx2.h"

namespace rayvec::avx2 {

#include "bvh/simd/box_lanes.inl"

using BoxLanes8 = BoxLanes<vfloat, 8>;
using BoxLanes16 = BoxLanes<vfloat, 16>;

}  // namespace rayvec::avx2
