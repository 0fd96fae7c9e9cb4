// Packet traversal of a WideBvh for any-hit queries (shadow rays of a camera tile toward one light,
// visibility segments from one origin): P = 16 rays (one zmm on AVX-512, two ymm on AVX2), one per
// lane, walk the tree together with a mask of the lanes that have no hit yet. A child box is tested
// against all of them at once and entered when any enters it; a leaf is intersected by a ray-packet
// kernel (one triangle against every lane per step: mt_packet_occluded, watertight_packet_occluded)
// for this unit's float `mt` and `watertight` tables, else ray by ray through the table. A lane
// leaves the packet at its first hit, and the packet ends when every lane has one. Children are
// entered front to back (by the entry distance of their lowest hit lane) when the caller expects
// most lanes to be occluded — the nearest occluders end them soonest — and in node order otherwise:
// a lane that reaches its end unoccluded visits every child it enters whatever the order, and the
// sort's branches cost (benchmarks.md#decision-any-hit-packets). When only kSingleRayLanes or fewer
// lanes remain in a subtree, they finish it by single-ray traversal (bvh_occluded_from), as the
// closest-hit packets do.
//
// Same answers as the single-ray query ray by ray: a ray is occluded when some triangle passes the
// kernel's test for it (and its filter), whatever the order the leaves come in; the packet kernels
// test each (ray, triangle) with the single-ray kernels' arithmetic bit for bit, and the box tests
// (packet_traversal.inl's) never drop a box the exact ray enters. Included by the ISA units after
// packet_traversal.inl (kThisIsa; pfloat: packet_lanes_<isa>.h).

// The any-hit leaf kernel of a packet, chosen once per packet.
enum class PacketAnyLeaf { ray_by_ray, mt, watertight };

// The per-packet state of the any-hit traversal: the leaf kernel with its rays (q for mt, wq and
// tlimit for watertight) and the lanes' filters (null or one per lane).
struct PacketAnyRun {
  PacketAnyLeaf leaf;
  const MtAnyHitRay<pfloat>& q;
  const WatertightPacketRays<pfloat>& wq;
  pfloat tlimit;
  const HitFilter* filters;
};

// The lanes of `lanes` occluded within the leaf `ref`.
template <class Children>
RAYVEC_INLINE unsigned packet_leaf_occluded(const TriangleArrays& tris, const TriangleKernels& kernels,
                                            const Ray* rays, uint32_t ref, unsigned lanes,
                                            const PacketAnyRun& run, const Children& children) {
  const uint32_t begin = leaf_begin(ref), end = leaf_end(ref);
  if (run.leaf == PacketAnyLeaf::mt)
    return mt_packet_occluded<pfloat>(tris, begin, end, children.template slots<true>(tris, begin, end),
                                      run.q, lanes, run.filters);
  if (run.leaf == PacketAnyLeaf::watertight)
    return watertight_packet_occluded<pfloat>(tris, begin, children.template slots<false>(tris, begin, end),
                                              run.wq, run.tlimit, lanes, run.filters);
  unsigned found = 0;
  for (unsigned m = lanes; m != 0; m &= m - 1) {
    const int k = __builtin_ctz(m);
    if (kernels.occluded(tris, begin, end, rays[k], run.filters ? &run.filters[k] : nullptr))
      found |= 1u << k;
  }
  return found;
}

// The traversal proper, from the root with the lanes `lanes`; box tests by `boxes`, children
// pre-tested by `children` (both from with_packet_boxes). Returns the occluded lanes. Leaf: the
// single-ray leaf policy of the table, for lanes that finish a subtree alone.
template <class B, class Leaf, bool Ordered, class Boxes, bool WithHull>
unsigned bvh_packet_occlude(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                            const Ray* rays, unsigned lanes, Boxes& boxes,
                            PacketChildren<B, WithHull>& children, const PacketAnyRun& run) {
  constexpr int N = B::N;
  const WideNode<N>* nodes = static_cast<const WideNode<N>*>(bvh.nodes);
  const unsigned packet = lanes;
  unsigned open = lanes;  // the lanes without a hit yet
  struct Item {
    uint32_t ref;
    uint32_t lanes;
  };
  Item local[kLocalStack];
  Item* stack = bvh.stack_size <= kLocalStack
                    ? local
                    : static_cast<Item*>(__builtin_alloca(bvh.stack_size * sizeof(Item)));
  uint32_t sp = 0;
  uint32_t ref = 0;
  for (;;) {
    if (__builtin_popcount(lanes) <= kSingleRayLanes) {  // diverged: finish ray by ray
      for (unsigned m = lanes; m != 0; m &= m - 1) {
        const int k = __builtin_ctz(m);
        const HitFilter* filter = run.filters ? &run.filters[k] : nullptr;
        if (bvh_occluded_from<B, Leaf>(bvh, tris, kernels, rays[k], filter, ref)) open &= ~(1u << k);
      }
      if (open == 0) break;
    } else if (!(ref & kLeafFlag)) {
      const WideNode<N>& node = nodes[ref];
      alignas(64) float tn[pfloat::W];
      float dist[N];  // Ordered: the entry distances of stack[base ..]
      const uint32_t base = sp;
      for (unsigned cm = children.of(node.bounds); cm != 0; cm &= cm - 1) {
        const int c = __builtin_ctz(cm);
        if (node.ref[c] == kEmptyRef) break;  // the used children come first
        const unsigned m = boxes.template hits<N>(node.bounds, c, lanes, tn);
        if (m == 0) continue;
        uint32_t j = sp++;
        if constexpr (Ordered) {  // insertion by entry distance, farthest deepest
          const float d = tn[__builtin_ctz(m)];
          for (; j > base && dist[j - 1 - base] < d; --j) {
            stack[j] = stack[j - 1];
            dist[j - base] = dist[j - 1 - base];
          }
          dist[j - base] = d;
        }
        stack[j] = Item{node.ref[c], m};
        prefetch_ref<N>(nodes, tris, node.ref[c]);
      }
      if (sp > base) {  // enter the last child pushed (Ordered: the nearest)
        --sp;
        ref = stack[sp].ref;
        lanes = stack[sp].lanes;
        continue;
      }
    } else if (ref != kEmptyRef) {
      open &= ~packet_leaf_occluded(tris, kernels, rays, ref, lanes, run, children);
      if (open == 0) break;
    }
    // pop, dropping entries whose lanes all have a hit
    for (;;) {
      if (sp == 0) return packet & ~open;
      --sp;
      lanes = stack[sp].lanes & open;
      if (lanes != 0) break;
    }
    ref = stack[sp].ref;
  }
  return packet & ~open;
}

// Any-hit queries of rays[0..P) for the lanes `active` (the other rays not read), traversed as one
// packet: bit k of the result is set when occluded(rays[k], filters ? &filters[k] : nullptr) holds
// — tmin <= t <= tmax, the filter accepting the triangle (filters: null or one per lane). A ray
// BvhAccelerator would reject (NaN or infinite origin or direction, NaN tmin or tmax) is not occluded.
// `ordered`: children front to back (the same answers either way).
template <class B, class PK, class Leaf>
unsigned bvh_occluded_packet(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                             const Ray* rays, unsigned active, const HitFilter* filters, bool ordered) {
  constexpr int P = PK::P;
  static_assert(pfloat::W == P, "the packet leaf kernel has one ray per lane");
  PacketRows s;
  active = load_packet<PK>(bvh, rays, active, s);
  if (active == 0) return 0;
  PacketAnyLeaf leaf = PacketAnyLeaf::ray_by_ray;
  if (kernels.isa == kThisIsa && kernels.intersector == Intersector::mt) leaf = PacketAnyLeaf::mt;
  if (kernels.isa == kThisIsa && kernels.intersector == Intersector::watertight)
    leaf = PacketAnyLeaf::watertight;
  // per lane the single-ray kernels' constants (mt_any_hit_ray, watertight_any_limit), formed in
  // lanes: written lane by lane and read back as vectors they stall on store forwarding
  const pfloat tmin = pfloat::load(s.soa[6]);
  const pfloat limit = next_up(pfloat::load(s.soa[7]));
  const MtAnyHitRay<pfloat> q{{pfloat::load(s.soa[0]), pfloat::load(s.soa[1]), pfloat::load(s.soa[2]),
                               pfloat::load(s.soa[3]), pfloat::load(s.soa[4]), pfloat::load(s.soa[5]), tmin},
                              mt_lower(tmin),
                              limit * pfloat::broadcast(kMtWiden),
                              limit};
  WatertightPacketRays<pfloat> wq;  // set only for the watertight leaf
  if (leaf == PacketAnyLeaf::watertight) {
    const float* const o[3] = {s.soa[0], s.soa[1], s.soa[2]};
    const float* const d[3] = {s.soa[3], s.soa[4], s.soa[5]};
    set_watertight_packet_rays<pfloat>(wq, o, d, s.soa[6], active);
  }
  const PacketAnyRun run{leaf, q, wq, limit, filters};
  unsigned occluded = 0;
  with_packet_boxes<B, PK>(
      bvh, s, active, [&](auto& boxes, auto& children) __attribute__((always_inline)) {
        occluded =
            ordered
                ? bvh_packet_occlude<B, Leaf, true>(bvh, tris, kernels, rays, active, boxes, children, run)
                : bvh_packet_occlude<B, Leaf, false>(bvh, tris, kernels, rays, active, boxes, children, run);
      });
  return occluded;
}
