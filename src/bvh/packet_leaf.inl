// The ray-packet leaf kernel of the float `mt` intersector: P rays (one per lane of V, the packet's
// SoA rays) against ONE triangle per step, the triangle's values broadcast to every lane — so a
// leaf of L triangles costs L vector steps for the whole packet instead of one single-ray kernel
// call (setup, steps, lane reduction) per active lane (Wald, Slusallek, Benthin & Wagner 2001; the
// layout of Embree's packet intersectors, transposed from Sena et al. 2018's one ray × W triangles).
// Included by the BVH ISA units (bvh_traversal_<isa>.cpp) after mt_float.inl, inside
// namespace rayvec::<isa>; used by packet_traversal.inl.
//
// Exactness: each lane gets exactly what the single-ray `mt` kernel (closest_mt_float) gives for
// its ray on the same slot range — same triangle id, bit-identical t, u, v, ties to the lowest id.
// The arithmetic is mt_numerator_values and the ordered tests of mt_any_hit_step's pre-test (only the
// triangle comes broadcast instead of loaded, its edges from rows subtracted once per leaf; the
// brute-force kernel's conservative one-mask sign pre-test skips the steps no lane can pass;
// benchmarks.md#decision-packet-leaf-kernel), then the same exact stage t = tn/|det| with
// tmin <= t < best, and u = (0 − un)/|det|, v = vn/|det| for the winner. Slots are visited in increasing
// order with a strict `<`, so of equal t the lowest slot, hence the lowest id (ids increase inside a range),
// wins, as in the single-ray lane reduction; the comparison with the lane's previous hit (earlier leaves) is
// mt_finish's. The upper pre-test threshold is per lane here (its own best·(1 + 2^-20)) where the single-ray
// kernel shares the nearest of its lanes; both are conservative (every triangle that can be nearer passes),
// so the exact stage alone decides — outside subnormal |det|, where no pre-test product is accurate to 2^-20
// and the two layouts may disagree about a hit that far from normal range. Of a leaf's slots [begin, end)
// the kernels step those set in `slots` (leaf_slot_bits' layout): all of them, or for a uniform forward
// packet those packet_slot_cull.inl's SlotCull keeps, which changes no answer.
//
// Float `mt` has this kernel and float `watertight` its own (watertight_packet_leaf.inl); paper, mt64
// and watertight64 packets keep the per-lane fallback (the single-ray kernel per active lane), as does
// an `mt` packet whose lanes mix tmin = 0 with tmin != 0 (the single-ray kernel's tmin = 0 pre-test differs
// from the general one for an overflowing |det|, so each kind has its own packet variant and mixing them is
// left out).

// The packet's rays as lanes, and per lane the pre-test's lower factor mt_lower(tmin).
template <class V>
struct MtPacketRays {
  RayLanes<V> r;
  V lo;
};

// A leaf's edges e2 = v2 − v0 and e1 = v1 − v0 and its normals ng = e2 × e1 as nine rows (x, y, z
// of e2, of e1, then of ng: row k < 6 is kRowV2 + k's edge), formed W slots at a time once per leaf
// instead of once per triangle and packet step (benchmarks.md#decision-packet-leaf-edges). The same
// float operations per value as the single-ray kernels' at.edge and at.normal, so bit-identical.
// Slot i is at i − first in every row, first being the leaf's first block start; a leaf of
// kMaxLeafTriangles slots spans at most three blocks.
struct MtLeafEdges {
  static constexpr uint32_t kStride = 3 * kSlotBlock;
  static constexpr uint32_t kRowNormal = 6;
  alignas(64) float row[9][kStride];
  uint32_t first;
};

template <class V>
RAYVEC_INLINE void mt_leaf_edges(const TriangleArrays& T, uint32_t begin, uint32_t end, MtLeafEdges& e) {
  e.first = begin / kSlotBlock * kSlotBlock;
  for (uint32_t b = e.first; b < end; b += kSlotBlock) {
    const float* block = T.v0x + slot_offset(b);
    float* to = &e.row[0][b - e.first];
    for (uint32_t j = 0; j < kSlotBlock; j += V::W) {
      const MtTriangleLanes<V> at{block + j};
      V edge[6];
      for (uint32_t k = 0; k < 6; ++k) edge[k] = at.edge(kRowV2 + k, at(kRowV0 + k % 3));
      const MtNormal<V> ng = mt_normal(edge[3], edge[4], edge[5], edge[0], edge[1], edge[2]);
      for (uint32_t k = 0; k < 6; ++k) edge[k].store(to + k * MtLeafEdges::kStride + j);
      ng.x.store(to + MtLeafEdges::kRowNormal * MtLeafEdges::kStride + j);
      ng.y.store(to + (MtLeafEdges::kRowNormal + 1) * MtLeafEdges::kStride + j);
      ng.z.store(to + (MtLeafEdges::kRowNormal + 2) * MtLeafEdges::kStride + j);
    }
  }
}

// One triangle, slot i, broadcast to every lane (the `at` of mt_numerator_values), its edges and
// normal from the leaf's rows.
template <class V>
struct MtTriangleBroadcast {
  const float* p;  // T.v0x + slot_offset(i)
  const float* e;  // &edges.row[0][i − edges.first]
  RAYVEC_INLINE V operator()(uint32_t row) const { return V::broadcast(p[row * kSlotBlock]); }
  RAYVEC_INLINE V edge(uint32_t row, V) const {
    return V::broadcast(e[(row - kRowV2) * MtLeafEdges::kStride]);
  }
  RAYVEC_INLINE MtNormal<V> normal() const {
    constexpr uint32_t n = MtLeafEdges::kRowNormal * MtLeafEdges::kStride;
    return {V::broadcast(e[n]), V::broadcast(e[n + MtLeafEdges::kStride]),
            V::broadcast(e[n + 2 * MtLeafEdges::kStride])};
  }
};
template <class V>
RAYVEC_INLINE MtTriangleBroadcast<V> mt_broadcast(const TriangleArrays& T, const MtLeafEdges& e, uint32_t i) {
  return {T.v0x + slot_offset(i), &e.row[0][i - e.first]};
}

// The end of a packet leaf: the lanes in `found` have a nearest hit in the leaf, t, u, v and the
// slot's bits in `slot`; each replaces its lane's previous hit (earlier leaves) when nearer (equal
// t: lower id), as the single-ray kernels' final comparison does, and lowers that lane's limit and
// initial. Returns the lanes whose hit changed.
template <class V>
RAYVEC_INLINE unsigned packet_leaf_finish(const TriangleArrays& T, unsigned found, V t_best, V u, V v, V slot,
                                          float* limit, float* initial, Hit* hits) {
  constexpr int P = V::W;
  alignas(64) float ts[P], us[P], vs[P], ss[P];
  t_best.store(ts);
  u.store(us);
  v.store(vs);
  slot.store(ss);
  unsigned changed = 0;
  for (unsigned m = found; m != 0; m &= m - 1) {
    const int k = __builtin_ctz(m);
    const float t = ts[k];
    const int32_t id = T.id[slot_offset(__builtin_bit_cast(uint32_t, ss[k]))];
    Hit& hit = hits[k];
    if (t < hit.t || (t == hit.t && (hit.tri < 0 || id < hit.tri))) {
      hit = Hit{t + 0.0f, us[k], vs[k], id};  // no −0, as mt_finish
      changed |= 1u << k;
    }
  }
  // the limits lowered in lanes: read back as vectors by the traversal and the next leaf, lane-wise
  // stores would stall on store forwarding
  if (changed != 0) {
    const V lim = V::load(limit);
    const typename V::Mask lower = mask_from_bits(V{}, changed) & (t_best < lim);
    select(lower, lim, t_best).store(limit);
    select(lower, V::load(initial), next_up(t_best)).store(initial);
  }
  return changed;
}

// The slots set in `slots` (of [begin, end)) against the lanes set in `lanes`. Per lane k: limit[k] =
// min(tmax_k, hits[k].t) and initial[k] = next_up(limit[k]) on entry (accepting t == limit, so a lower id at
// the same t still wins); hits[k], limit[k] and initial[k] are updated where a lane finds a nearer
// hit (equal t: lower id). TminZero: every lane in `lanes` has tmin == 0. Returns the lanes whose
// hit changed.
template <class V, bool TminZero>
unsigned mt_packet_closest(const TriangleArrays& T, uint32_t begin, uint32_t end, uint64_t slots,
                           const MtPacketRays<V>& q, unsigned lanes, float* limit, float* initial,
                           Hit* hits) {
  const typename V::Mask active = mask_from_bits(V{}, lanes);
  const V zero = V::broadcast(0.0f), widen = V::broadcast(kMtWiden);
  V best_t = V::load(initial);
  V hi = best_t * widen;
  V un = zero, vn = zero, adet = zero, slot = zero;
  unsigned found = 0;
  const V neg_lo = zero - q.lo;
  // the exact tests and the update of one step that passed the pre-test
  auto step = [&](MtNumerators<V> c, uint32_t i) __attribute__((always_inline)) {
    // no `tn < hi·|det|` here (the pre-test's sign form has filtered on it; the exact t < best_t
    // below decides): hi·|det| underflows to 0 once a lane's nearest hit is at t = 0, and would drop
    // a tie there that the single-ray kernel's exact test takes
    c.mask = active & mt_edges(c);
    if constexpr (TminZero)
      c.mask = c.mask & (c.tn >= zero);
    else
      c.mask = c.mask & (c.tn >= q.lo * c.adet);
    if (!any(c.mask)) return;
    // the exact depth test of mt_closest_step, per lane
    const V t = c.tn / c.adet;
    const typename V::Mask m = c.mask & (t >= q.r.tmin) & (t < best_t);
    if (!any(m)) return;
    best_t = select(m, best_t, t);
    un = select(m, un, c.un);
    vn = select(m, vn, c.vn);
    adet = select(m, adet, c.adet);
    slot = select(m, slot, V::broadcast(__builtin_bit_cast(float, i)));  // the slot's bits
    hi = best_t * widen;
    found |= bits(m);
  };
  MtLeafEdges edges;
  mt_leaf_edges<V>(T, begin, end, edges);
  // Two triangles per iteration, one branch on both pre-tests (benchmarks.md#decision-packet-leaf-kernel);
  // the steps that pass are still taken in slot order.
  for_slot_pairs(
      edges.first, slots,
      [&](uint32_t i, uint32_t j) __attribute__((always_inline)) {
        const MtNumerators<V> c0 = mt_numerator_values<V>(mt_broadcast<V>(T, edges, i), q.r);
        const MtNumerators<V> c1 = mt_numerator_values<V>(mt_broadcast<V>(T, edges, j), q.r);
        const unsigned p0 = bits(mt_sign_pretest<V, TminZero>(c0, active, neg_lo, hi));
        const unsigned p1 = bits(mt_sign_pretest<V, TminZero>(c1, active, neg_lo, hi));
        if ((p0 | p1) == 0) return;
        if (p0) step(c0, i);
        if (p1) step(c1, j);  // its pre-test used the older, larger hi: still conservative
      },
      [&](uint32_t i) __attribute__((always_inline)) {
        const MtNumerators<V> c = mt_numerator_values<V>(mt_broadcast<V>(T, edges, i), q.r);
        if (any(mt_sign_pretest<V, TminZero>(c, active, neg_lo, hi))) step(c, i);
      },
      [] { return true; });
  if (found == 0) return 0;
  // u and v divided once, as mt_finish does (0 − un: no −0)
  return packet_leaf_finish<V>(T, found, best_t, (zero - un) / adet, vn / adet, slot, limit, initial, hits);
}

// The lanes of `hit` (lanes that hit slot i) whose filter accepts the slot's triangle: every one of
// them when `filters` is null, else lane k asks filters[k], as the single-ray any-hit kernels ask
// theirs of each triangle they hit.
RAYVEC_INLINE unsigned packet_filter_accepts(const TriangleArrays& T, uint32_t i, unsigned hit,
                                             const HitFilter* filters) {
  if (!filters) return hit;
  const int32_t id = T.id[slot_offset(i)];
  for (unsigned m = hit; m != 0; m &= m - 1) {
    const int k = __builtin_ctz(m);
    if (filters[k].ignore(filters[k].context, id)) hit &= ~(1u << k);
  }
  return hit;
}

// The slots set in `slots` (of [begin, end)) against the lanes set in `lanes`: the lanes that hit one
// of them with tmin <= t <= tmax and whose filter (filters: null or one per lane) accepts it. `q`: the
// packet's rays as lanes with, per lane, the single-ray kernel's constants (mt_any_hit_ray's lo, hi, tlimit).
// Per lane and triangle the single-ray kernel's test, mt_any_hit_lanes, on the numerators mt_packet_closest
// forms, behind the conservative sign pre-test, so a lane is occluded here exactly when the single-ray kernel
// finds its ray occluded in the same range (outside subnormal |det|, mt_packet_closest's caveat). A lane
// leaves the loop at its first hit.
template <class V>
unsigned mt_packet_occluded(const TriangleArrays& T, uint32_t begin, uint32_t end, uint64_t slots,
                            const MtAnyHitRay<V>& q, unsigned lanes, const HitFilter* filters) {
  const V neg_lo = V::broadcast(0.0f) - q.lo;
  unsigned found = 0;
  // the exact tests of one triangle that passed the pre-test
  auto step = [&](const MtNumerators<V>& c, uint32_t i) __attribute__((always_inline)) {
    const typename V::Mask m = mt_any_hit_lanes<V>(c, mask_from_bits(V{}, lanes), q);
    if (!any(m)) return;
    const unsigned hit = packet_filter_accepts(T, i, bits(m), filters);
    found |= hit;
    lanes &= ~hit;
  };
  MtLeafEdges edges;
  mt_leaf_edges<V>(T, begin, end, edges);
  // Two triangles per iteration, one branch on both sign pre-tests (conservative: every lane the
  // exact tests accept passes them; mt_sign_pretest), as mt_packet_closest does.
  for_slot_pairs(
      edges.first, slots,
      [&](uint32_t i, uint32_t j) __attribute__((always_inline)) {
        const typename V::Mask active = mask_from_bits(V{}, lanes);
        const MtNumerators<V> c0 = mt_numerator_values<V>(mt_broadcast<V>(T, edges, i), q.r);
        const MtNumerators<V> c1 = mt_numerator_values<V>(mt_broadcast<V>(T, edges, j), q.r);
        const unsigned p0 = bits(mt_sign_pretest<V, false>(c0, active, neg_lo, q.hi));
        const unsigned p1 = bits(mt_sign_pretest<V, false>(c1, active, neg_lo, q.hi));
        if ((p0 | p1) == 0) return;
        if (p0) step(c0, i);
        if (p1) step(c1, j);
      },
      [&](uint32_t i) __attribute__((always_inline)) {
        const MtNumerators<V> c = mt_numerator_values<V>(mt_broadcast<V>(T, edges, i), q.r);
        if (any(mt_sign_pretest<V, false>(c, mask_from_bits(V{}, lanes), neg_lo, q.hi))) step(c, i);
      },
      [&] { return lanes != 0; });
  return found;
}
