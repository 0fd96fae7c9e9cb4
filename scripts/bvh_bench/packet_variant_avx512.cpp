// A variant packet traversal for packet_bench: the packet .inl named by -DRV_PACKET_INL (by default
// the tree's own bvh/bvh_packet.inl) compiled as an AVX-512 unit in its own namespace
// (-DRV_VARIANT_NS), registered under -DRV_VARIANT_NAME. Several copies of this unit, each with its
// own .inl or -D knobs, link into one packet_bench.
#include <cstdint>

#include "bvh/bvh_kernels.h"
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx512.h"
#include "kernels/simd/box_lanes_avx512.h"
#include "kernels/simd/packet_lanes_avx512.h"

#ifndef RV_PACKET_INL
#define RV_PACKET_INL "bvh/bvh_packet.inl"
#endif
#ifndef RV_PACKET_LANES
#define RV_PACKET_LANES PacketLanes16
#endif

namespace rayvec::pbench {
using PacketFn = void (*)(const BvhArrays&, const TriangleArrays&, const TriangleKernels&, const Ray*,
                          Hit*, unsigned);
void register_variant(const char* name, PacketFn fn);
}  // namespace rayvec::pbench

namespace rayvec::avx512::RV_VARIANT_NS {
constexpr Isa kThisIsa = Isa::avx512;
#include "bvh/bvh_traversal.inl"
#include "kernels/moller_trumbore.inl"
#include "kernels/mt_packet.inl"
#include RV_PACKET_INL

void closest_packet(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                    const Ray* rays, Hit* hits, unsigned active) {
  if (bvh.width == 16) bvh_closest_packet<BoxLanes16, RV_PACKET_LANES>(bvh, tris, kernels, rays, hits, active);
  else bvh_closest_packet<BoxLanes8, RV_PACKET_LANES>(bvh, tris, kernels, rays, hits, active);
}
struct Registrar {
  Registrar() { pbench::register_variant(RV_VARIANT_NAME, &closest_packet); }
} registrar;
}  // namespace rayvec::avx512::RV_VARIANT_NS
