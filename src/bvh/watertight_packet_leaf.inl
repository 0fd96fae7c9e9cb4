// The ray-packet leaf kernel of the float `watertight` intersector (Woop, Benthin & Wald 2013): P rays
// (one per lane of V) against ONE triangle per step, the triangle's vertices broadcast to every lane,
// as packet_leaf.inl does for `mt` (benchmarks.md#decision-watertight-packet-leaf). Included by the
// BVH ISA units (bvh_traversal_<isa>.cpp) after watertight.inl and packet_leaf.inl, inside namespace
// rayvec::<isa>; used by packet_traversal.inl.
//
// Exactness: each lane gets exactly what the single-ray kernel (watertight_closest) gives for its ray
// on the same slot range — same triangle id, bit-identical t, u, v, ties to the lowest id — because
// both run the one body watertight_lanes: the single-ray kernel with the ray broadcast and W
// triangles loaded, this kernel with the rays as lanes and one triangle broadcast. Each lane has the
// permutation (kx, ky, kz) of its own ray: the per-lane origin and shear are formed once per packet
// (set_watertight_packet_rays: the same correctly rounded divisions as watertight_ray), and a leaf is
// stepped once for each permutation its lanes use, reading that permutation's vertex rows — a
// camera packet's rays share their dominant axis and sign, so nearly always once. Within a lane,
// slots are visited in increasing order with a strict `<` against the lane's nearest t, so of equal
// t the lowest slot, hence the lowest id, wins, as in the single-ray lane reduction; the comparison
// with the lane's previous hit (earlier leaves) is packet_leaf_finish's. The t bound, the double
// refinement of zero edge functions and the zero-area test are the single-ray kernel's, lane by lane
// (the zero-area test once per triangle). No tmin pre-test, so packets may mix tmin = 0 and tmin != 0.
// A uniform forward packet skips the slots no lane's kernel test can accept (packet_slot_cull.inl's
// SlotCull, which says why that changes no answer).
//
// Only float `watertight` has a packet leaf besides `mt`: watertight64 (and mt64, paper) packets keep
// the per-lane fallback through the kernel table — the double kernels step half as many lanes and
// are not render's default.

// The packet's rays in ray space, lane by lane: the origin permuted to the lane's own (kx, ky, kz)
// and the shear Sx, Sy, Sz of watertight_ray; lanes[c] the lanes whose permutation is c = 2·kz +
// (d[kz] < 0).
template <class V>
struct WatertightPacketRays {
  V ox, oy, oz, sx, sy, sz, tmin;
  unsigned lanes[6];
};

// Per lane, x where on_x, y where on_y, z elsewhere (on_x and on_y disjoint).
template <class V>
RAYVEC_INLINE V pick_axis(typename V::Mask on_x, typename V::Mask on_y, V x, V y, V z) {
  return select(on_y, select(on_x, z, x), y);
}

// Sets q from the packet's SoA rows (o[3], d[3] and tmin of P rays); only the lanes of `active`
// (finite rays) are used later. Filled in place: a returned copy moves the scalar lane masks with
// vector loads that wait on their just-made stores (store forwarding fails).
template <class V>
RAYVEC_INLINE void set_watertight_packet_rays(WatertightPacketRays<V>& q, const float* const o[3],
                                              const float* const d[3], const float* tmin, unsigned active) {
  const V o0 = V::load(o[0]), o1 = V::load(o[1]), o2 = V::load(o[2]);
  const V d0 = V::load(d[0]), d1 = V::load(d[1]), d2 = V::load(d[2]);
  const V a0 = abs(d0), a1 = abs(d1), a2 = abs(d2);
  // kz = the axis of largest |d|, exactly as watertight_ray chooses it
  const unsigned b01 = bits(a0 > a1), b02 = bits(a0 > a2), b12 = bits(a1 > a2);
  const unsigned z0 = b01 & b02, z1 = ~b01 & b12, z2 = active & ~(z0 | z1);
  const typename V::Mask on0 = mask_from_bits(V{}, z0), on1 = mask_from_bits(V{}, z1);
  const V dz = pick_axis<V>(on0, on1, d0, d1, d2);
  // kx = kz + 1, ky = kz + 2 (mod 3), swapped where d[kz] < 0 (keeps the winding)
  const typename V::Mask swap = dz < V::broadcast(0.0f);
  const V ox = pick_axis<V>(on0, on1, o1, o2, o0), oy = pick_axis<V>(on0, on1, o2, o0, o1);
  const V dx = pick_axis<V>(on0, on1, d1, d2, d0), dy = pick_axis<V>(on0, on1, d2, d0, d1);
  q.ox = select(swap, ox, oy);
  q.oy = select(swap, oy, ox);
  q.oz = pick_axis<V>(on0, on1, o0, o1, o2);
  q.sx = select(swap, dx, dy) / dz;
  q.sy = select(swap, dy, dx) / dz;
  q.sz = V::broadcast(1.0f) / dz;
  q.tmin = V::load(tmin);
  const unsigned neg = bits(swap);
  const unsigned by_axis[3] = {z0 & active, z1 & active, z2};
  for (int kz = 0; kz < 3; ++kz) {
    q.lanes[2 * kz] = by_axis[kz] & ~neg;
    q.lanes[2 * kz + 1] = by_axis[kz] & neg;
  }
}

// The ray lanes of `q` with the vertex rows of permutation c.
template <class V>
RAYVEC_INLINE WatertightRay<V> watertight_packet_class(const TriangleArrays& T,
                                                       const WatertightPacketRays<V>& q, int c) {
  const int kz = c >> 1;
  int kx = kz == 2 ? 0 : kz + 1;
  int ky = kx == 2 ? 0 : kx + 1;
  if (c & 1) {
    const int k = kx;
    kx = ky;
    ky = k;
  }
  const float* const v0[3] = {T.v0x, T.v0y, T.v0z};
  const float* const v1[3] = {T.v1x, T.v1y, T.v1z};
  const float* const v2[3] = {T.v2x, T.v2y, T.v2z};
  return WatertightRay<V>{v0[kx], v0[ky], v0[kz], v1[kx], v1[ky], v1[kz], v2[kx], v2[ky],
                          v2[kz], q.ox,   q.oy,   q.oz,   q.sx,   q.sy,   q.sz,   q.tmin};
}

// One triangle, slot i, broadcast to every lane.
template <class V>
struct WatertightBroadcast {
  uint32_t k;  // slot_offset(i)
  RAYVEC_INLINE V operator()(const float* row) const { return V::broadcast(row[k]); }
};

// Every lane tests the same triangle: a zero-area one drops them all.
template <class V>
struct NonzeroAreaTriangle {
  const TriangleArrays& T;
  uint32_t i;
  RAYVEC_INLINE typename V::Mask operator()(typename V::Mask m) const {
    return zero_area(T, i) ? mask_from_bits(V{}, 0) : m;
  }
};

// The slots set in `slots` (leaf_slot_bits' layout from leaf_first(begin): every slot of the leaf,
// or those SlotCull keeps, packet_slot_cull.inl) against the lanes set in `lanes`, with limit, initial
// and hits as mt_packet_closest takes and updates them. Returns the lanes whose hit changed.
template <class V>
unsigned watertight_packet_closest(const TriangleArrays& T, uint32_t begin, uint64_t slots,
                                   const WatertightPacketRays<V>& q, unsigned lanes, float* limit,
                                   float* initial, Hit* hits) {
  const uint32_t first = leaf_first(begin);
  const V zero = V::broadcast(0.0f);
  V best_t = V::load(initial);  // lanes still at `initial` have no hit
  V un = zero, vn = zero, slot = zero;
  unsigned found = 0;
  for (int c = 0; c < 6; ++c) {
    const unsigned class_lanes = lanes & q.lanes[c];
    if (class_lanes == 0) continue;
    const WatertightRay<V> r = watertight_packet_class<V>(T, q, c);
    const typename V::Mask active = mask_from_bits(V{}, class_lanes);
    for (uint64_t m = slots; m != 0; m &= m - 1) {
      const uint32_t i = first + uint32_t(__builtin_ctzll(m));
      const LaneHits<V> h = watertight_lanes<V>(r, WatertightBroadcast<V>{slot_offset(i)},
                                                NonzeroAreaTriangle<V>{T, i}, active, best_t);
      if (!any(h.mask)) continue;
      // nearest t, u, v and slot, blended as the single-ray kernel does
      best_t = select(h.mask, best_t, h.t);
      un = select(h.mask, un, h.u);
      vn = select(h.mask, vn, h.v);
      slot = select(h.mask, slot, V::broadcast(__builtin_bit_cast(float, i)));  // the slot's bits
      found |= bits(h.mask);
    }
  }
  if (found == 0) return 0;
  return packet_leaf_finish<V>(T, found, best_t, un, vn, slot, limit, initial, hits);
}

// The slots set in `slots` (as for watertight_packet_closest) against the lanes set in `lanes`: the
// lanes that hit one of them with tmin <= t < tlimit (per lane: next_up(tmax), watertight_any_limit)
// and whose filter (filters: null or one per lane) accepts it — per lane and triangle the single-ray
// any-hit kernel's test (watertight_lanes), so the same occlusion. A lane leaves the loop at its
// first hit.
template <class V>
unsigned watertight_packet_occluded(const TriangleArrays& T, uint32_t begin, uint64_t slots,
                                    const WatertightPacketRays<V>& q, V tlimit, unsigned lanes,
                                    const HitFilter* filters) {
  const uint32_t first = leaf_first(begin);
  unsigned found = 0;
  for (int c = 0; c < 6; ++c) {
    unsigned class_lanes = lanes & q.lanes[c];
    if (class_lanes == 0) continue;
    const WatertightRay<V> r = watertight_packet_class<V>(T, q, c);
    for (uint64_t m = slots; m != 0 && class_lanes != 0; m &= m - 1) {
      const uint32_t i = first + uint32_t(__builtin_ctzll(m));
      const LaneHits<V> h =
          watertight_lanes<V>(r, WatertightBroadcast<V>{slot_offset(i)}, NonzeroAreaTriangle<V>{T, i},
                              mask_from_bits(V{}, class_lanes), tlimit);
      if (!any(h.mask)) continue;
      const unsigned hit = packet_filter_accepts(T, i, bits(h.mask), filters);
      found |= hit;
      class_lanes &= ~hit;
    }
  }
  return found;
}
