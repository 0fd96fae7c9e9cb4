// AVX-512 lane types of the wide-BVH box tests (bvh/simd/box_lanes.inl): vfloat8, a ymm of 8 floats
// with AVX-512VL mask compares, for a WideNode<8> (BoxLanes8), and vfloat, a zmm of 16, for a
// WideNode<16> (BoxLanes16; also the 16-ray packets), one register per bounds row. Included only by
// *_avx512.cpp units; the box test body is compiled in namespace rayvec::avx512.
#pragma once
#include <utility>

#include "simd/vfloat_avx512.h"

namespace rayvec::avx512 {

#include "bvh/simd/box_lanes.inl"

using BoxLanes8 = BoxLanes<vfloat8, 8>;
using BoxLanes16 = BoxLanes<vfloat, 16>;

}  // namespace rayvec::avx512
