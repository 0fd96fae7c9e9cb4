// A variant packet traversal for packet_bench: the packet .inl named by -DRV_PACKET_INL (by default
// the tree's own bvh/bvh_packet.inl) compiled as an AVX-512 unit (or, with -DRV_AVX2, an AVX2 one:
// RV_ISA=avx2 packet_build.sh) in its own namespace (-DRV_VARIANT_NS), registered under
// -DRV_VARIANT_NAME. Several copies of this unit, each with its own .inl or -D knobs, link into one
// packet_bench.
#include <cstdint>

#include "bvh/bvh_kernels.h"
#include "kernels/kernel_table.h"
#ifdef RV_AVX2
#include "kernels/simd/vfloat_avx2.h"
#include "kernels/simd/box_lanes_avx2.h"
#include "kernels/simd/packet_lanes_avx2.h"
#define RV_ISA avx2
#define RV_DEFAULT_LANES PacketLanes8
#else
#include "kernels/simd/vfloat_avx512.h"
#include "kernels/simd/box_lanes_avx512.h"
#include "kernels/simd/packet_lanes_avx512.h"
#define RV_ISA avx512
#define RV_DEFAULT_LANES PacketLanes16
#endif

#ifndef RV_PACKET_INL
#define RV_PACKET_INL "bvh/bvh_packet.inl"
#endif
#ifndef RV_PACKET_LANES
#define RV_PACKET_LANES RV_DEFAULT_LANES
#endif

namespace rayvec::pbench {
using PacketFn = void (*)(const BvhArrays&, const TriangleArrays&, const TriangleKernels&, const Ray*,
                          Hit*, unsigned);
void register_variant(const char* name, PacketFn fn);
}  // namespace rayvec::pbench

namespace rayvec::RV_ISA::RV_VARIANT_NS {
constexpr Isa kThisIsa = Isa::RV_ISA;
#include "bvh/bvh_traversal.inl"
#include "kernels/moller_trumbore.inl"
#include "kernels/mt_packet.inl"
#include RV_PACKET_INL

// The bench's 16-ray tiles: one packet, or two of 8 rays on AVX2.
void closest_packet(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                    const Ray* rays, Hit* hits, unsigned active) {
  constexpr int P = RV_PACKET_LANES::P;
  for (int h = 0; h < 16 / P; ++h) {
    const unsigned part = (active >> (P * h)) & ((1u << P) - 1u);
    if (part == 0) continue;
    if (bvh.width == 16)
      bvh_closest_packet<BoxLanes16, RV_PACKET_LANES>(bvh, tris, kernels, rays + P * h, hits + P * h, part);
    else
      bvh_closest_packet<BoxLanes8, RV_PACKET_LANES>(bvh, tris, kernels, rays + P * h, hits + P * h, part);
  }
}
struct Registrar {
  Registrar() { pbench::register_variant(RV_VARIANT_NAME, &closest_packet); }
} registrar;
}  // namespace rayvec::RV_ISA::RV_VARIANT_NS
