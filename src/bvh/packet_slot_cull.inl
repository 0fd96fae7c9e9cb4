// Which triangles of a leaf a ray packet steps. The packet leaf kernels (packet_leaf.inl,
// watertight_packet_leaf.inl) step one triangle against all lanes at a time, so their cost grows with
// the leaf's triangles — and leaves are sized for single rays, which test 8 or 16 triangles in one
// kernel step (benchmarks.md#decision-leaf-size, #decision-merged-leaves). A uniform forward packet
// (every tmin >= 0, one direction sign per axis: camera tiles, shadow rays toward one light) first
// tests the boxes of all the leaf's triangles against the hull of its lanes — the hull pre-test of a
// node's children (box_lanes.inl, hits_hull) with each triangle's box in place of a child's — and
// steps only the triangles whose box the hull enters — in the trees of small and medium meshes,
// where a leaf's triangles are large beside a packet's footprint (BvhArrays::packet_slot_cull,
// kPacketSlotCullBelow; benchmarks.md#decision-packet-slot-cull).
// Included by the BVH ISA units (bvh_traversal_<isa>.cpp) after their box lanes, inside namespace
// rayvec::<isa>; used by the packet leaf kernels and packet_traversal.inl.
//
// Why no answer changes. A kernel decides with rounded arithmetic, so a triangle it reports may lie
// off the exact ray by the rounding error; the cull keeps every triangle the exact ray, as a line
// from its origin on (t >= 0), passes within that error of. The hull is tested over t in [0, inf)
// rather than each lane's [tmin, tmax]: a reported t may stray far from the exact one (t is
// ill-conditioned for rays that graze the plane; a reported hit lies in front of the origin, as the
// kernels accept t >= tmin >= 0, and for `watertight` t exceeds its own rounding error). The slab
// test never drops a box the exact line enters. The error, with s = max(|o| over the lanes,
// |coordinates| of the root box) the packet's scale, |v − o| <= 2·√3·s:
// - `watertight` decides on the triangle sheared into the ray's space (kernels/watertight.inl), whose
//   vertices are v − o and a shear, each rounded: the decision is the exact one for that triangle
//   moved by a few units in the last place of |v − o|, and a move in ray space is a world offset from
//   the ray no larger. Margin: 2^-14·s, at least 2^-14 / (2·√3) of |v − o|, about 300 units in the
//   last place.
// - `mt`'s numerators (u, v: triple products of v0 − o, d and an edge) carry errors of a few units
//   in the last place of |v − o|·|d|·|e|; as a ray offset that is divided by the sine of the angle
//   between d and the edge, which is at least the sine of the angle φ between d and the triangle's
//   plane, and det's error scales the third edge the same way. So a triangle is always stepped
//   unless sin φ >= kGraze = 2^-6 for every lane: tested as sin φ0 >= kGraze + sin θ, φ0 the angle
//   of the packet's first direction d0 and θ the widest angle between d0 and a lane's direction
//   (then φ >= φ0 − θ >= asin(kGraze), asin being superadditive), on the stored normals where the
//   tree has them; the others' boxes are widened by 2^-10·s: at least 2^-10 / (2·√3) of |v − o|,
//   4,700 units in the last place, 74 after the grazing factor of 64.
// So every triangle the kernel could report for some lane is stepped, in slot order as before: the
// same ids, t, u, v bit for bit (tests/bvh/bvh_packet_slot_cull_test.cpp). Packets that are not
// uniform and forward (no hull) step every slot.

// A leaf's slots [begin, end) as bits: bit j for slot first + j, first = leaf_first(begin) (a leaf
// spans at most three blocks of kSlotBlock: 48 bits).
RAYVEC_INLINE uint32_t leaf_first(uint32_t begin) { return begin / kSlotBlock * kSlotBlock; }
RAYVEC_INLINE uint64_t leaf_slot_bits(uint32_t begin, uint32_t end) {
  const uint32_t first = leaf_first(begin);
  return ((uint64_t(1) << (end - first)) - 1) & ~((uint64_t(1) << (begin - first)) - 1);
}

// Calls pair(i, j) for the slots set in `slots` (leaf_slot_bits' layout, from `first`) two at a time
// in increasing order while keep() holds, and one(i) for an odd last one.
template <class Pair, class One, class Keep>
RAYVEC_INLINE void for_slot_pairs(uint32_t first, uint64_t slots, const Pair& pair, const One& one,
                                  const Keep& keep) {
  while (slots != 0 && keep()) {
    const uint32_t i = first + uint32_t(__builtin_ctzll(slots));
    slots &= slots - 1;
    if (slots == 0) {
      one(i);
      return;
    }
    const uint32_t j = first + uint32_t(__builtin_ctzll(slots));
    slots &= slots - 1;
    pair(i, j);
  }
}

// The sine below which `mt` counts a triangle as grazed by the packet (see above).
inline constexpr float kGraze = 0x1p-6f;

// How a uniform forward packet culls triangles: its hull over t in [0, inf) (the hull is the
// packet's, PacketChildren's, passed in) and the margins its triangle boxes are widened by.
struct SlotCull {
  bool on;          // BvhArrays::packet_slot_cull: else every slot
  float margin;     // watertight
  float margin_mt;  // mt
  float d0[3];      // mt: the direction of the packet's first lane
  float graze2;     // mt: (kGraze + sin θ)²·|d0|², θ the widest angle between d0 and a lane's direction

  // The slots of [begin, end) whose triangle box, widened by the margin, the hull enters, in
  // leaf_slot_bits' layout. The boxes are formed from the triangle rows a block at a time, laid out
  // as a 16-wide node's child boxes; padding slots (zero area) may pass or not: no kernel reports them.
  // Mt: also every triangle that a lane's direction may meet at a sine below kGraze (see above).
  template <bool Mt>
  RAYVEC_INLINE uint64_t slots(const TriangleArrays& T, uint32_t begin, uint32_t end,
                               const PacketHull& hull) const {
    if (!on) return leaf_slot_bits(begin, end);
    const uint32_t first = leaf_first(begin);
    const vfloat m = vfloat::broadcast(Mt ? margin_mt : margin);
    uint64_t found = 0;
    for (uint32_t b = first; b < end; b += kSlotBlock) {
      const float* block = T.v0x + slot_offset(b);
      alignas(64) float box[6][kSlotBlock];  // lo x, y, z, hi x, y, z
      unsigned grazed = 0;
      for (uint32_t j = 0; j < kSlotBlock; j += vfloat::W) {
        vfloat v0[3], v1[3], v2[3];
        for (uint32_t a = 0; a < 3; ++a) {
          v0[a] = vfloat::load(block + (kRowV0 + a) * kSlotBlock + j);
          v1[a] = vfloat::load(block + (kRowV1 + a) * kSlotBlock + j);
          v2[a] = vfloat::load(block + (kRowV2 + a) * kSlotBlock + j);
          (vmin(vmin(v0[a], v1[a]), v2[a]) - m).store(box[a] + j);
          (vmax(vmax(v0[a], v1[a]), v2[a]) + m).store(box[3 + a] + j);
        }
        if constexpr (Mt) {
          const float* ng =
              T.ng ? T.ng + normal_offset(b) + j : nullptr;  // stored: below 2^18 triangles mostly
          const MtNormal<vfloat> n = ng ? MtNormal<vfloat>{vfloat::load(ng), vfloat::load(ng + kSlotBlock),
                                                           vfloat::load(ng + 2 * kSlotBlock)}
                                        : mt_normal(v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2],
                                                    v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2]);
          const vfloat dn = fmadd(vfloat::broadcast(d0[0]), n.x,
                                  fmadd(vfloat::broadcast(d0[1]), n.y, vfloat::broadcast(d0[2]) * n.z));
          const vfloat n2 = fmadd(n.x, n.x, fmadd(n.y, n.y, n.z * n.z));
          // not grazed where (d0·n)² >= (kGraze + sin θ)²·|d0|²·|n|² (NaN: grazed)
          grazed |= (~bits(dn * dn >= vfloat::broadcast(graze2) * n2) & ((1u << vfloat::W) - 1u)) << j;
        }
      }
      found |= uint64_t(BoxLanes16::hits_hull(box, hull, 0.0f, __builtin_inff()) | grazed) << (b - first);
    }
    return found & leaf_slot_bits(begin, end);
  }
};

// The cull of a packet of scale s (see above), d[a] the rows of its directions.
RAYVEC_INLINE SlotCull slot_cull(bool on, float s, const pfloat d[3], unsigned active) {
  SlotCull c;
  c.on = on;
  if (!on) return c;
  c.margin = s * 0x1p-14f;
  c.margin_mt = s * 0x1p-10f;
  // sin² of each lane's angle to d0: |d × d0|² / (|d|²·|d0|²)
  alignas(64) float rows[3][pfloat::W];
  for (int a = 0; a < 3; ++a) d[a].store(rows[a]);
  const int k0 = __builtin_ctz(active);
  const float x = rows[0][k0], y = rows[1][k0], z = rows[2][k0];
  const pfloat bx = pfloat::broadcast(x), by = pfloat::broadcast(y), bz = pfloat::broadcast(z);
  const pfloat cx = d[1] * bz - d[2] * by, cy = d[2] * bx - d[0] * bz, cz = d[0] * by - d[1] * bx;
  const float d02 = x * x + y * y + z * z;
  const pfloat sin2 =
      (cx * cx + cy * cy + cz * cz) / ((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * pfloat::broadcast(d02));
  const float sin_widest = __builtin_sqrtf(hmax_lanes(sin2, active)) * (1.0f + 0x1p-10f);  // rounded up
  const float limit = kGraze + sin_widest;
  c.d0[0] = x;
  c.d0[1] = y;
  c.d0[2] = z;
  c.graze2 = limit * limit * d02;
  return c;
}
