// Which triangles of a leaf a `watertight` ray packet steps. The packet leaf kernel
// (watertight_packet_leaf.inl) steps one triangle against all lanes at a time, so its cost grows
// with the leaf's triangles — and leaves are sized for single rays, which test 8 or 16 triangles in
// one kernel step (benchmarks.md#decision-leaf-size, #decision-merged-leaves). A uniform forward
// packet (every tmin >= 0, one direction sign per axis: camera tiles, shadow rays toward one light)
// first tests the boxes of all the leaf's triangles against the hull of its lanes — the hull
// pre-test of a node's children (box_lanes.inl, hits_hull) with each triangle's box in place of a
// child's — and steps only the triangles whose box the hull enters
// (benchmarks.md#decision-packet-slot-cull). Included by the BVH ISA units (bvh_traversal_<isa>.cpp)
// after their box lanes, inside namespace rayvec::<isa>; used by watertight_packet_leaf.inl and
// packet_traversal.inl.
//
// Why no answer changes. `watertight` decides a hit on the triangle sheared into the ray's space
// (kernels/watertight.inl), whose vertices are v − o and a shear, each rounded: the decision is the
// exact one for that triangle moved by a few units in the last place of |v − o| <= |v| + |o|, and a
// move in ray space is a world offset from the ray no larger. So the exact ray, as a line from its
// origin on (t >= 0; a reported t exceeds its own rounding error, so the hit is in front), passes
// within that distance of every triangle the kernel can report for it. Each triangle's box is
// widened on every side by a margin of 2^-14 of the packet's scale s = max(|o| over its lanes,
// |coordinates| of the root box), at least 2^-14 / (2·√3) of |v − o| — about 300 units in the last
// place — and the hull is tested over t in [0, inf) rather than each lane's [tmin, tmax], since a
// reported t may stray further (t is ill-conditioned for rays that graze the plane). The slab test
// never drops a box the exact line enters, so every triangle the kernel could report for some lane is
// stepped, in slot order as before: the same ids, t, u, v bit for bit
// (tests/bvh/bvh_packet_slot_cull_test.cpp). Float `mt` has no such bound — its barycentric
// numerators lose accuracy as the ray turns parallel to an edge, by no fixed margin — so `mt` packets
// step every slot, as do packets that are not uniform and forward (no hull).

// A leaf's slots [begin, end) as bits: bit j for slot first + j, first = leaf_first(begin) (a leaf
// spans at most three blocks of kSlotBlock: 48 bits).
RAYVEC_INLINE uint32_t leaf_first(uint32_t begin) { return begin / kSlotBlock * kSlotBlock; }
RAYVEC_INLINE uint64_t leaf_slot_bits(uint32_t begin, uint32_t end) {
  const uint32_t first = leaf_first(begin);
  return ((uint64_t(1) << (end - first)) - 1) & ~((uint64_t(1) << (begin - first)) - 1);
}

// The hull of a uniform forward packet in vfloat lanes over t in [0, inf), and the margin its
// triangle boxes are widened by.
struct SlotCull {
  BoxHull<vfloat> hull;
  float margin;

  // The slots of [begin, end) whose triangle box, widened by the margin, the hull enters, in
  // leaf_slot_bits' layout. The boxes are formed from the triangle rows a block at a time, laid out
  // as a 16-wide node's child boxes; padding slots (zero area) may pass or not: no kernel reports them.
  RAYVEC_INLINE uint64_t slots(const TriangleArrays& T, uint32_t begin, uint32_t end) const {
    const uint32_t first = leaf_first(begin);
    const vfloat m = vfloat::broadcast(margin);
    uint64_t found = 0;
    for (uint32_t b = first; b < end; b += kSlotBlock) {
      const float* block = T.v0x + slot_offset(b);
      alignas(64) float box[6][kSlotBlock];  // lo x, y, z, hi x, y, z
      for (uint32_t j = 0; j < kSlotBlock; j += vfloat::W)
        for (uint32_t a = 0; a < 3; ++a) {
          const vfloat v0 = vfloat::load(block + (kRowV0 + a) * kSlotBlock + j);
          const vfloat v1 = vfloat::load(block + (kRowV1 + a) * kSlotBlock + j);
          const vfloat v2 = vfloat::load(block + (kRowV2 + a) * kSlotBlock + j);
          (vmin(vmin(v0, v1), v2) - m).store(box[a] + j);
          (vmax(vmax(v0, v1), v2) + m).store(box[3 + a] + j);
        }
      found |= uint64_t(BoxLanes16::hits_hull(box, hull, __builtin_inff())) << (b - first);
    }
    return found & leaf_slot_bits(begin, end);
  }
};

// The cull of a packet whose hull is h and scale s (see above).
RAYVEC_INLINE SlotCull slot_cull(PacketHull h, float s) {
  h.tmin = 0.0f;
  return {BoxLanes16::prepare_hull(h), s * 0x1p-14f};
}
