// The AVX2 twin of packet_variant_avx512.cpp (RV_ISA=avx2 packet_bench): a variant packet traversal for packet_bench: the packet .inl named by -DRV_PACKET_INL (by default
// the tree's own bvh/bvh_packet.inl) compiled as an AVX-512 unit in its own namespace
// (-DRV_VARIANT_NS), registered under -DRV_VARIANT_NAME. Several copies of this unit, each with its
// own .inl or -D knobs, link into one packet_bench.
#include <cstdint>

#include "bvh/bvh_kernels.h"
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx2.h"
#include "kernels/simd/box_lanes_avx2.h"
#include "kernels/simd/packet_lanes_avx2.h"

#ifndef RV_PACKET_INL
#define RV_PACKET_INL "bvh/bvh_packet.inl"
#endif
#ifndef RV_PACKET_LANES
#define RV_PACKET_LANES PacketLanes8
#endif

namespace rayvec::pbench {
using PacketFn = void (*)(const BvhArrays&, const TriangleArrays&, const TriangleKernels&, const Ray*,
                          Hit*, unsigned);
void register_variant(const char* name, PacketFn fn);
}  // namespace rayvec::pbench

namespace rayvec::avx2::RV_VARIANT_NS {
constexpr Isa kThisIsa = Isa::avx2;
#include "bvh/bvh_traversal.inl"
#include "kernels/moller_trumbore.inl"
#include "kernels/mt_packet.inl"
#include RV_PACKET_INL

void closest_packet(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                    const Ray* rays, Hit* hits, unsigned active) {
  // 16-ray tiles as two 8-ray packets
  for (int h = 0; h < 2; ++h) {
    const unsigned half = (active >> (8 * h)) & 0xffu;
    if (half == 0) continue;
    if (bvh.width == 16) bvh_closest_packet<BoxLanes16, RV_PACKET_LANES>(bvh, tris, kernels, rays + 8 * h, hits + 8 * h, half);
    else bvh_closest_packet<BoxLanes8, RV_PACKET_LANES>(bvh, tris, kernels, rays + 8 * h, hits + 8 * h, half);
  }
}
struct Registrar {
  Registrar() { pbench::register_variant(RV_VARIANT_NAME, &closest_packet); }
} registrar;
}  // namespace rayvec::avx2::RV_VARIANT_NS
