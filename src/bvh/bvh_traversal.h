// BvhTraversal: the traversal functions one (ISA, node width) pair provides, chosen once per BVH
// (bvh_traversal.cpp) like the triangle kernel table, never per ray.
#pragma once
#include <cstddef>
#include <string_view>

#include "bvh/wide_bvh.h"
#include "kernels/triangle_kernels.h"

namespace rayvec {

// How the single-ray traversals reach the leaf kernel (benchmarks.md#decision-direct-leaf-call,
// #decision-inlined-leaf). Same results every way.
enum class LeafCall {
  table,    // through the kernel table: every intersector
  direct,   // the ISA's float `mt` or `watertight` kernel called directly, out of line
  inlined,  // as direct, but the closest-hit kernel inlined into the traversal loop
};

// "table", "direct" or "inlined".
const char* leaf_call_name(LeafCall call);

struct BvhTraversal {
  Isa isa;
  int width;  // children per node this table traverses

  // Closest hit of `ray` (finite origin and direction) as TriangleKernels::closest defines it, over
  // the whole tree; `hit` must be a miss or a previous result for the same ray.
  void (*closest)(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                  const Ray& ray, Hit& hit);
  // Any hit (finite origin and direction) accepted by `filter` (may be null); exits at the first.
  bool (*occluded)(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                   const Ray& ray, const HitFilter* filter);
  // Closest hits of the rays rays[k] for the lanes k set in `active` (k < packet_width; the other
  // rays are not read), traversed as one packet: each hits[k] is overwritten with what closest()
  // gives from a miss (a miss for a ray BvhAccelerator would reject: NaN or infinite origin or direction, NaN
  // tmin or tmax). Null when the ISA has no packets.
  void (*closest_packet)(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                         const Ray* rays, Hit* hits, unsigned active);
  // Any-hit queries of the rays rays[k] for the lanes k set in `active` (k < packet_width; the
  // other rays not read), traversed as one packet: bit k of the result is occluded(rays[k],
  // filters ? &filters[k] : nullptr) (filters: null or one per lane); `ordered`: children front to
  // back, for packets whose lanes are expected to be mostly occluded (the same answers either way).
  // Null when the ISA has no packets.
  unsigned (*occluded_packet)(const BvhArrays& bvh, const TriangleArrays& tris,
                              const TriangleKernels& kernels, const Ray* rays, unsigned active,
                              const HitFilter* filters, bool ordered);
  int packet_width;  // rays per packet (16 on AVX-512 and AVX2, 0 none)
  // How the leaves reach the kernel (default_leaf_call): other than `table`, a float kernel of this
  // ISA directly — `mt` in closest() (on AVX2 also in occluded()), `watertight` in both; `inlined`:
  // the closest() kernel inlined. AVX-512's occluded() calls its float `mt` kernel directly
  // whatever this says.
  LeafCall leaf_call = LeafCall::table;
};

// The node widths an ISA has traversal code for.
struct BvhWidths {
  int widths[3];
  int count;
};
BvhWidths bvh_widths(Isa isa);

// The node width a BVH over `triangles` triangles gets by default on a CPU whose cpuid vendor is
// `vendor`: 16 on AVX-512 and AVX2 from kWideNodeTriangles triangles up (deep trees: fewer levels,
// so fewer dependent node fetches per ray), else 8 — except AVX-512 on Intel, 16 at every size
// (small meshes gain there and lose on AMD; see benchmarks.md#decision-node-width for the numbers
// of each vendor). The two-argument form uses the running CPU's vendor.
inline constexpr std::size_t kWideNodeTriangles = 32768;
int default_bvh_width(Isa isa, std::size_t triangles, std::string_view vendor);
int default_bvh_width(Isa isa, std::size_t triangles);

// How many kernel steps (blocks of the kernel's width) a leaf of the binned SAH over `triangles`
// triangles may hold by default: one for the SIMD ISAs below kWideNodeTriangles (small meshes:
// packets and shadow rays gain up to 18 % on Intel and AMD alike, incoherent rays lose up to 6 %),
// two otherwise — one step there traces shadow and incoherent rays up to 10 % faster on Intel but
// builds 5–15 % slower, which a render of one sample a pixel does not win back
// (benchmarks.md#decision-leaf-size).
int default_leaf_steps(Isa isa, std::size_t triangles);

// How the traversals reach the leaf kernel of `intersector` in a BVH over `triangles` triangles.
// `mt` and `watertight` on AVX2 and AVX-512: the float kernel directly, where the closest-hit
// traversal then keeps its ray registers instead of saving and reloading them around every leaf call
// (single rays faster on Intel and AMD alike: benchmarks.md#decision-direct-leaf-call); on AVX2 the
// any-hit traversal then calls its leaf kernel directly too, with the ray's lanes formed once per ray
// (benchmarks.md#decision-any-hit-leaf-lanes); AVX-512's any-hit traversal always does. `watertight`:
// both traversals, the ray's shear formed once per ray (bvh/watertight_leaf.inl;
// benchmarks.md#decision-watertight-leaf). Both from kWideNodeTriangles triangles up: the
// closest-hit kernel inlined (large trees, whose rays wait on leaves from memory, gain from a leaf
// without a call's saves and reloads; small ones lose: benchmarks.md#decision-inlined-leaf). Other
// intersectors and the scalar ISA: the table. Same results every way.
LeafCall default_leaf_call(Isa isa, Intersector intersector, std::size_t triangles);

// The table for (isa, width) with `call`'s leaves where the ISA has them for `intersector` (else the
// nearest it has: inlined → direct → table); the ISA must be supported and the width one of
// bvh_widths(isa).
const BvhTraversal& bvh_traversal(Isa isa, int width, LeafCall call,
                                  Intersector intersector = Intersector::mt);

namespace scalar {
const BvhTraversal* bvh_traversal(int width, LeafCall call, Intersector intersector);
}
namespace avx2 {
const BvhTraversal* bvh_traversal(int width, LeafCall call, Intersector intersector);
}
namespace avx512 {
const BvhTraversal* bvh_traversal(int width, LeafCall call, Intersector intersector);
}

}  // namespace rayvec
