// WideBvh: the binary SAH tree collapsed into nodes of N = 4, 8 or 16 children whose boxes are stored
// as structure-of-arrays, so one SIMD step tests a ray against all N boxes (Wald et al. 2008
// "Getting Rid of Packets"; Embree's BVH4/BVH8). Leaves are ranges of slots of one TriangleSoA built
// in leaf order, so the leaf intersector is the triangle kernel table.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "bvh/binary_bvh.h"
#include "platform/large_buffer.h"

namespace rayvec {

// A child reference: an inner node's index, a leaf (kLeafFlag | begin << 5 | count − 1, so a leaf
// holds 1..32 triangles and begins below slot 2^26), or kEmptyRef for an unused slot.
inline constexpr uint32_t kLeafFlag = 0x80000000u;
inline constexpr uint32_t kEmptyRef = 0xffffffffu;
inline constexpr uint32_t kMaxLeafTriangles = 32;
inline constexpr uint32_t kMaxLeafBegin = 1u << 26;
// Relative widening of every ray–box interval (see single_ray_traversal.inl): 2^-18.
inline constexpr float kDefaultBoxEpsilon = 1.0f / 262144.0f;

// One node: bounds[0..2] = lo x, y, z and bounds[3..5] = hi x, y, z of each child, child k in lane k.
// Unused slots have lo = +inf, hi = −inf (no ray with finite origin and direction enters them) and
// ref = kEmptyRef. Plain data with no member functions: the ISA units read it.
template <int N>
struct alignas(64) WideNode {
  float bounds[6][N];
  uint32_t ref[N];
};

// What the traversal kernels see. Node 0 is the root (an empty mesh has a root with no children).
struct BvhArrays {
  const void* nodes;  // WideNode<width>[node_count]
  uint32_t width;
  uint32_t node_count;
  // entries a traversal stack needs: depth · (width − 1) pushed at most, + 1 for the entry the
  // single-ray closest-hit traversal writes above its top without pushing it
  uint32_t stack_size;
  float box_epsilon;  // relative widening of ray–box intervals (kDefaultBoxEpsilon)
  // the union of the root's child boxes, the bounds of the whole tree (lo = +inf, hi = −inf when
  // there are none): the packets' first test (packet_traversal.inl)
  float root_lo[3], root_hi[3];
  // uniform forward packets step only the leaf triangles their hull can reach (packet_slot_cull.inl)
  bool packet_slot_cull;
};

// How the binary tree is collapsed: greedily, a wide node opening its inner child of the highest
// priority until it is full — the child of largest surface area (the SAH's choice for the node
// itself), or the one with the most triangles (keeps the subtrees left below a node of similar size,
// so the bottom levels can come out full). lower_sah_cost runs both and keeps the tree of the lower
// sah_node_cost() (on the first one's side when equal).
enum class CollapseRule { lower_sah_cost, largest_area, most_triangles };

class WideBvh {
 public:
  WideBvh() = default;
  // Collapses `tree` (leaves of at most kMaxLeafTriangles) into nodes of `width` ∈ {4, 8, 16}
  // children by `rule` (wide_bvh.cpp says why the default runs both). With merge_slots > 0, an
  // inner binary node that a full wide node leaves as its child, and whose leaves all lie within
  // merge_slots consecutive slots, becomes one leaf over those slots instead of a wide node of its
  // own (such nodes held 2–4 leaves); the range may then cover padding slots between its leaves
  // (zero area, id −1: no kernel reports them). Throws std::length_error when there are 2^26 or
  // more triangles, std::invalid_argument when merge_slots exceeds kMaxLeafTriangles.
  WideBvh(const BinaryBvh& tree, int width, CollapseRule rule = CollapseRule::lower_sah_cost,
          uint32_t merge_slots = 0);

  const BvhArrays& arrays() const { return arrays_; }
  int width() const { return int(arrays_.width); }
  uint32_t node_count() const { return arrays_.node_count; }
  uint32_t depth() const { return depth_; }  // levels of wide nodes, the root being level 1
  uint32_t leaf_count() const { return leaves_; }
  std::size_t bytes() const { return bytes_; }
  // SAH node cost: Σ over wide nodes of the half surface area of the node's box (the union of its
  // children's boxes), as accumulated in double over float areas.
  double sah_node_cost() const { return sah_cost_; }
  // SAH cost of the whole tree relative to its root box: Σ over wide nodes of their box's surface
  // area, plus Σ over leaves of the leaf's box area times the kernel steps it takes (aligned groups
  // of `step_slots` slots), a node visit and a kernel step weighed alike. The measure two leaf
  // sizings of one mesh are compared by (BvhAccelerator; benchmarks.md#decision-leaf-block-choice).
  double sah_cost(uint32_t step_slots) const;
  // Changes the relative widening of ray–box intervals (must stay > 0: with 0, an infinite slab
  // distance times 0 is NaN and the box is missed).
  void set_box_epsilon(float eps) { arrays_.box_epsilon = eps; }
  void set_packet_slot_cull(bool on) { arrays_.packet_slot_cull = on; }

 private:
  LargeBuffer storage_;
  BvhArrays arrays_{};
  uint32_t depth_ = 0, leaves_ = 0;
  std::size_t bytes_ = 0;
  double sah_cost_ = 0;
};

// Sorts the triangle ids of each leaf's slot range in `order` (the tree's BinaryBvh::order), padding
// slots last. A merged leaf (WideBvh's merge_slots) joins the ranges of several binary leaves, each
// sorted on its own; the kernels' tie rule (of equal t, the first slot wins) needs the whole range
// sorted to return the lowest id, as brute force does. Other leaves are already sorted.
void sort_leaf_slots(const WideBvh& tree, std::vector<uint32_t>& order);

}  // namespace rayvec
