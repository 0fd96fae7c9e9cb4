// BvhAccelerator: the accelerator for real scenes — a binned-SAH tree (bvh/binary_bvh.h) collapsed into
// a wide BVH (bvh/wide_bvh.h) whose leaves are slot ranges of one TriangleSoA in leaf order, so the
// leaf intersector is the triangle kernel table of the configured ISA and intersector. Returns
// exactly what BruteForce returns (same ids and t; equal t: lowest id).
#pragma once
#include "accel/accelerator.h"
#include "bvh/binary_bvh.h"
#include "bvh/bvh_traversal.h"
#include "bvh/wide_bvh.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {

struct BvhOptions {
  SahConfig sah;
  // Size leaves to the triangle kernel (benchmarks.md#decision-leaf-size): SAH leaf cost per
  // kernel-width block of triangles and up to default_leaf_steps blocks per leaf (AVX-512: 16 and
  // 32, AVX2: 8 and 16; one block for small meshes, costed per half block instead where that
  // tree's cost is lower: #decision-leaf-block-choice; scalar keeps sah's 4 and 8). false: use
  // sah.max_leaf and sah.leaf_block as given.
  bool leaves_from_kernel = true;
  // With leaves_from_kernel: the most kernel steps a SAH leaf holds; 0 = default_leaf_steps.
  int leaf_steps = 0;
  int width = 0;  // children per node: 0 = default_bvh_width(isa, triangles)
  // A subtree that a full node leaves as its child becomes one leaf when its triangles fit in this
  // many kernel steps (at most 32 slots; 0: never): a leaf test instead of a node of 2–4 leaves
  // (benchmarks.md#decision-merged-leaves).
  int merge_steps = 3;
  float box_epsilon = kDefaultBoxEpsilon;  // relative widening of ray-box intervals, > 0
  // How the traversals reach the leaf kernel: a LeafCall as an int (0 table, 1 direct, 2 inlined),
  // or −1 = default_leaf_call(isa, intersector, triangles). Where the ISA and intersector have no
  // such leaf, the nearest they have (bvh_traversal). Same results every way.
  int leaf_call = -1;
  // Whether the triangle rows store the normals the float `mt` kernels read (12 bytes a slot) or
  // leave the kernels to form them per step: −1 = bvh_normals' default, 1 = stored for `mt`, 0 =
  // never stored. No other intersector reads them. Same hits either way.
  int stored_normals = -1;
  // Whether uniform forward packets step only the leaf triangles their hull can reach
  // (bvh/packet_slot_cull.inl): 1 = always, 0 = never, −1 = below kPacketSlotCullBelow triangles.
  // Same hits either way.
  int packet_slot_cull = -1;
};

// The memory budget of a BVH with its triangle rows, in bytes per triangle of the mesh.
inline constexpr double kBvhBytesPerTriangle = 64.0;
// From this many triangles the kernels form the normals: the leaves' rows no longer stay in cache,
// and fewer bytes a leaf pay for the arithmetic.
inline constexpr std::size_t kFormedNormalsFrom = std::size_t(1) << 18;
// Below this many triangles packets cull a leaf's triangles by their boxes (BvhOptions::packet_slot_cull):
// a 4×4 tile of a camera or of shadow rays reaches a few of a leaf's triangles. Above it, at the
// resolutions that frame such meshes, a tile spreads over about as many triangles as a leaf holds
// and the boxes cost more than they save (benchmarks.md#decision-packet-slot-cull).
inline constexpr std::size_t kPacketSlotCullBelow = std::size_t(1) << 18;

// Whether a BVH of `tree_bytes` over `slots` triangle slots (padding included) for a mesh of
// `triangles` stores the `mt` normals (BvhOptions::stored_normals): by default for `mt` on meshes
// below kFormedNormalsFrom triangles whose tree and rows with normals fit kBvhBytesPerTriangle
// (long triangles' spatial-split references do not) (benchmarks.md#decision-normal-budget).
Normals bvh_normals(Intersector intersector, int stored_normals, std::size_t tree_bytes, std::size_t slots,
                    std::size_t triangles);

// cos of the widest angle between a packet's first direction and another for closest_group to
// trace the group as a packet (about 8 degrees).
inline constexpr float kPacketCone = 0.99f;
// Whether rays[0, n) (n >= 1) point within kPacketCone of rays[0]'s direction, whatever their
// origins; false when a NaN is involved.
bool packet_aligned(const Ray* rays, std::size_t n);
// packet_aligned, and every ray has rays[0]'s origin.
bool packet_coherent(const Ray* rays, std::size_t n);

// Wall-clock seconds of a BvhAccelerator's build, stage by stage. Below kWideNodeTriangles two trees
// are built side by side and one is kept: `tree`, `align` and `collapse` are the kept one's, so the
// stages may add up to less than the whole build.
struct BvhBuildTimes {
  double tree = 0;      // the binned SAH build (build_binned_sah)
  double align = 0;     // align_leaves
  double collapse = 0;  // the wide tree (WideBvh)
  double sort = 0;      // sort_leaf_slots
  double fill = 0;      // the TriangleSoA
};

class BvhAccelerator final : public Accelerator {
 public:
  // Builds with omp_get_max_threads() threads. Throws std::length_error for 2^26 or more triangles.
  BvhAccelerator(const TriangleMesh& mesh, const TraceConfig& config, const BvhOptions& options = {});

  Hit closest(const Ray& ray) const override;
  bool occluded(const Ray& ray, const HitFilter* filter = nullptr) const override;
  Hit closest_counted(const Ray& ray, TraversalCost& cost) const override;
  bool occluded_counted(const Ray& ray, TraversalCost& cost) const override;
  // Consecutive groups of packet_width rays (16: one zmm on AVX-512, two ymm on AVX2) are traversed as
  // packets — best for coherent rays such as a 4×4 camera tile; results equal closest() ray by ray.
  void closest_stream(const Ray* rays, Hit* hits, std::size_t n) const override;
  // Packets for the groups of packet_width rays that share an origin and whose directions lie within
  // kPacketCone of the first ray's (a pinhole camera's rays in scan order); single rays for the
  // other groups, where diverging lanes make a packet slower than its rays one by one
  // (benchmarks.md#decision-batched-tracing).
  void closest_group(const Ray* rays, Hit* hits, std::size_t n) const override;
  // Packets for the groups of packet_width rays whose directions lie within kPacketCone of the
  // first ray's, whatever their origins (shadow rays of a camera tile toward a light, segments from
  // one origin); single rays for the other groups. Results equal occluded() ray by ray
  // (benchmarks.md#decision-any-hit-packets).
  void occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                       const HitFilter* filters = nullptr) const override;
  std::size_t stream_rays() const override { return 256; }
  std::size_t bytes() const override { return tris_.bytes() + tree_.bytes(); }
  const TraceConfig& config() const override { return config_; }

  const WideBvh& tree() const { return tree_; }
  const TriangleSoA& triangles() const { return tris_; }
  const BvhTraversal& traversal() const { return *traversal_; }  // the traversal table in use
  // The SAH's leaf block the tree was built with (SahConfig::leaf_block): the kernel's width, or on
  // small meshes half of it where that tree's cost is the lower.
  uint32_t leaf_block() const { return leaf_block_; }
  // The most kernel steps a SAH leaf could hold (BvhOptions::leaf_steps or its default); 0 where the
  // leaves were not sized to the kernel (BvhOptions::leaves_from_kernel false, or the scalar ISA).
  int leaf_steps() const { return leaf_steps_; }
  const BvhBuildTimes& build_times() const { return build_times_; }

 private:
  TraceConfig config_;
  WideBvh tree_;
  TriangleSoA tris_;
  const TriangleKernels* kernels_;
  const BvhTraversal* traversal_;
  uint32_t leaf_block_ = 0;
  int leaf_steps_ = 0;
  BvhBuildTimes build_times_;
};

}  // namespace rayvec
