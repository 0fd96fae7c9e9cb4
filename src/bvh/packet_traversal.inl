// Packet traversal of a WideBvh for coherent rays (a 4×4 camera tile): P = 16 rays (one zmm on
// AVX-512, two ymm on AVX2: pfloat), one per lane, walk the tree together with a mask of active
// lanes (Wald, Slusallek, Benthin & Wagner 2001; with wide nodes as in Embree's hybrid traversal).
// Each child box is tested against all active lanes at once; the children hit by any lane are
// visited front to back by the entry distance of their lowest hit lane, and dropped on pop once
// every lane has a nearer hit than the entry distance of their nearest lane. With the float `mt` or
// `watertight` table of this ISA a leaf is intersected by a ray-packet kernel (packet_leaf.inl,
// watertight_packet_leaf.inl: one triangle against all lanes per step, exactly the single-ray
// answer per lane); other intersectors, and `mt` packets mixing tmin = 0 with tmin != 0, intersect
// a leaf ray by ray with the triangle kernel table (two lanes per call through the table's pair
// kernel measured slower than one: packets 1.1x single rays instead of 1.5x). When only
// kSingleRayLanes or fewer lanes remain active in a subtree, the packet has diverged: those lanes
// finish that subtree by single-ray traversal (bvh_closest_from). Uniform forward packets first
// test every child of a node against the hull of their lanes (PacketChildren below) and then only
// the children it passes lane by lane. Box tests: packets whose lanes all have tmin >= 0 (camera
// rays) take the forward test (PK::Forward: one FMA a slab, the widening folded into the
// reciprocals as in the single-ray forward test, and without per-lane blends when all lanes share
// the direction signs); the others take the general test (PK::hits), as single_ray_traversal.inl's
// tmin < 0 rays do. Included by the ISA units after single_ray_traversal.inl, packet_leaf.inl and
// watertight_packet_leaf.inl (kThisIsa; pfloat: packet_lanes_<isa>.h).

inline constexpr int kSingleRayLanes = 2;

struct PacketItem {
  uint32_t ref;
  uint32_t lanes;
  float t;  // smallest entry distance of the lanes
};

// Lanes of `active` that may enter the box [lo, hi] (per axis): the slab test of
// PacketLanes::hits — the same subtract-then-multiply slabs, which are monotonic in the box planes,
// and the same widening, except that an infinite end stays infinite instead of becoming NaN — so a
// lane that enters any box inside [lo, hi] under the traversal's test is never dropped here.
RAYVEC_INLINE unsigned packet_box_lanes(const float lo[3], const float hi[3], const pfloat o[3],
                                        const pfloat r[3], pfloat tmin, pfloat tmax, float eps,
                                        unsigned active) {
  const pfloat zero = pfloat::broadcast(0.0f);
  pfloat tn = pfloat::broadcast(-__builtin_inff()), tf = pfloat::broadcast(__builtin_inff());
  for (int a = 0; a < 3; ++a) {
    const pfloat::Mask neg = r[a] < zero;  // near plane hi, far plane lo
    const pfloat bl = pfloat::broadcast(lo[a]), bh = pfloat::broadcast(hi[a]);
    tn = vmax((select(neg, bl, bh) - o[a]) * r[a], tn);  // a NaN slab (0·inf) is skipped
    tf = vmin((select(neg, bh, bl) - o[a]) * r[a], tf);
  }
  tn = vmin(fmadd(abs(tn), pfloat::broadcast(-eps), tn), tn);  // inf − inf = NaN: keep tn
  tf = vmax(fmadd(abs(tf), pfloat::broadcast(eps), tf), tf);
  return bits(vmax(tn, tmin) <= vmin(tf, tmax)) & active;
}

// The general box test (any tmin, any direction): PK's, with the widening per child.
template <class PK>
struct PacketBoxes {
  PK pk;
  float eps;
  template <int N>
  RAYVEC_INLINE unsigned hits(const float (*b)[N], int k, unsigned active, float* tn) const {
    return pk.template hits<N>(b, k, active, eps, tn);
  }
  RAYVEC_INLINE void set_tmax(const float* t) { pk.set_tmax(t); }
  RAYVEC_INLINE float max_tmax(unsigned lanes) const { return pk.max_tmax(lanes); }
};

// The leaf kernel of a packet (bvh_closest_packet chooses it once per packet).
enum class PacketLeaf {
  ray_by_ray,    // the table's single-ray kernel, lane by lane
  mt_tmin_zero,  // mt_packet_closest, every tmin = 0
  mt,            // mt_packet_closest, no tmin = 0
  watertight,    // watertight_packet_closest
};

// The per-packet state of the traversal: per-lane limits (see mt_packet_closest) and the leaf kernel
// with its rays (q for the mt kernels, wq for watertight).
struct PacketRun {
  float* tmax;     // min(tmax, hit.t) per lane
  float* initial;  // next_up(tmax) per lane
  PacketLeaf leaf;
  const MtPacketRays<pfloat>& q;
  const WatertightPacketRays<pfloat>& wq;
};

RAYVEC_INLINE float vmax_abs(float a, float b) {
  a = a < 0 ? -a : a;
  b = b < 0 ? -b : b;
  return a > b ? a : b;
}

// The memory a stack entry will read when popped: its node, or its leaf's triangle rows (the
// rows mt_packet_closest reads). Issued on push, so the loads overlap the nearer children's work
// (benchmarks.md#decision-prefetch).
template <int N>
RAYVEC_INLINE void prefetch_ref(const WideNode<N>* nodes, const TriangleArrays& t, uint32_t ref) {
  if (!(ref & kLeafFlag)) {
    const char* p = reinterpret_cast<const char*>(nodes + ref);
    for (std::size_t j = 0; j < sizeof(WideNode<N>); j += 64) __builtin_prefetch(p + j);
  } else if (ref != kEmptyRef) {
    // the hot rows of each block the leaf touches: kMtRows contiguous lines (triangle_soa.h)
    const uint32_t last = (leaf_end(ref) - 1) / kSlotBlock;
    for (uint32_t b = leaf_begin(ref) / kSlotBlock; b <= last; ++b) {
      const char* p = reinterpret_cast<const char*>(t.v0x + std::size_t(b) * kSlotBlockFloats);
      for (uint32_t j = 0; j < kMtRows; ++j) __builtin_prefetch(p + 64 * j);
    }
  }
}

// The children of a node that some lane of the packet may enter: all of them, or with a hull
// (uniform forward packets) those whose box the hull of the packet's lanes enters — one test of
// every child against the whole packet (B::hits_hull) instead of one test a child. A camera packet
// enters few of a wide node's children, so this skips most of the per-child tests
// (benchmarks.md#decision-hull-pretest). It only filters: a child it passes is tested lane by lane
// as before, so the results are unchanged bit for bit. slots<Mt>(): the slots of a leaf the packet
// kernels step — all of them, or with a hull those SlotCull keeps (packet_slot_cull.inl; Mt: the
// `mt` kernels' rule).
template <class B, bool WithHull>
struct PacketChildren;
template <class B>
struct PacketChildren<B, false> {
  RAYVEC_INLINE unsigned of(const float (*)[B::N]) const { return (1u << B::N) - 1u; }
  template <bool Mt>
  RAYVEC_INLINE uint64_t slots(const TriangleArrays&, uint32_t begin, uint32_t end) const {
    return leaf_slot_bits(begin, end);
  }
  RAYVEC_INLINE void set_tmax(float) {}
};
template <class B>
struct PacketChildren<B, true> {
  PacketHull hull;
  float tmax;  // the largest tmax of the packet's lanes
  SlotCull cull;
  RAYVEC_INLINE unsigned of(const float (*b)[B::N]) const { return B::hits_hull(b, hull, hull.tmin, tmax); }
  template <bool Mt>
  RAYVEC_INLINE uint64_t slots(const TriangleArrays& T, uint32_t begin, uint32_t end) const {
    return cull.template slots<Mt>(T, begin, end, hull);
  }
  RAYVEC_INLINE void set_tmax(float t) { tmax = t; }
};

// The traversal proper, from the root with the lanes `lanes`, box tests by `boxes` (PacketBoxes
// or PK::Forward), children pre-tested by `children`; the state set up by bvh_closest_packet.
// `boxes` and `children` by reference: passed by value, the box state's registers are copied onto
// the stack for every packet (rep movsq; benchmarks.md#decision-packet-box-by-reference).
template <class B, class PK, class Boxes, bool WithHull>
void bvh_packet_traverse(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                         const Ray* rays, Hit* hits, unsigned lanes, Boxes& boxes,
                         PacketChildren<B, WithHull>& children, const PacketRun& run) {
  constexpr int N = B::N;
  const unsigned packet = lanes;  // the lanes the hull covers
  constexpr int P = PK::P;
  const WideNode<N>* nodes = static_cast<const WideNode<N>*>(bvh.nodes);
  float* const tmax = run.tmax;
  float* const initial = run.initial;
  const PacketLeaf leaf = run.leaf;
  const MtPacketRays<pfloat>& q = run.q;
  PacketItem local[kLocalStack];
  PacketItem* stack = bvh.stack_size <= kLocalStack
                          ? local
                          : static_cast<PacketItem*>(__builtin_alloca(bvh.stack_size * sizeof(PacketItem)));
  uint32_t sp = 0;
  uint32_t ref = 0;
  for (;;) {
    if (__builtin_popcount(lanes) <= kSingleRayLanes) {  // diverged: finish ray by ray
      for (unsigned m = lanes; m != 0; m &= m - 1) {
        const int k = __builtin_ctz(m);
        bvh_closest_from<B>(bvh, tris, kernels, rays[k], hits[k], ref);
        if (hits[k].t < tmax[k]) {
          tmax[k] = hits[k].t;
          initial[k] = next_up(tmax[k]);
        }
      }
      boxes.set_tmax(tmax);
      children.set_tmax(boxes.max_tmax(packet));
    } else if (!(ref & kLeafFlag)) {
      const WideNode<N>& node = nodes[ref];
      uint32_t refs[N], masks[N];
      float ts[N];
      int idx[N];
      int count = 0;
      alignas(64) float tn[N][P];
      for (unsigned cm = children.of(node.bounds); cm != 0; cm &= cm - 1) {
        const int c = __builtin_ctz(cm);
        if (node.ref[c] == kEmptyRef) break;  // the used children come first
        const unsigned m = boxes.template hits<N>(node.bounds, c, lanes, tn[count]);
        if (m == 0) continue;
        // order by the entry distance of the lowest hit lane (one load; the lanes of a coherent
        // packet enter a box at nearly the same t); the minimum over the lanes, a reduction, is
        // taken only for the entries pushed, whose pop test needs it
        const float d = tn[count][__builtin_ctz(m)];
        const int h = count;
        int j = count++;
        while (j > 0 && ts[j - 1] < d) {  // descending: farthest first
          refs[j] = refs[j - 1];
          masks[j] = masks[j - 1];
          ts[j] = ts[j - 1];
          idx[j] = idx[j - 1];
          --j;
        }
        refs[j] = node.ref[c];
        masks[j] = m;
        ts[j] = d;
        idx[j] = h;
      }
      if (count > 0) {
        for (int j = 0; j < count - 1; ++j) {
          stack[sp++] = PacketItem{refs[j], masks[j], PK::min_lanes(tn[idx[j]], masks[j])};
          prefetch_ref<N>(nodes, tris, refs[j]);
        }
        ref = refs[count - 1];
        lanes = masks[count - 1];
        continue;
      }
    } else if (ref != kEmptyRef) {
      const uint32_t begin = leaf_begin(ref), end = leaf_end(ref);
      if (leaf == PacketLeaf::mt_tmin_zero) {
        mt_packet_closest<pfloat, true>(tris, begin, end, children.template slots<true>(tris, begin, end), q,
                                        lanes, tmax, initial, hits);
      } else if (leaf == PacketLeaf::mt) {
        mt_packet_closest<pfloat, false>(tris, begin, end, children.template slots<true>(tris, begin, end), q,
                                         lanes, tmax, initial, hits);
      } else if (leaf == PacketLeaf::watertight) {
        watertight_packet_closest<pfloat>(tris, begin, children.template slots<false>(tris, begin, end),
                                          run.wq, lanes, tmax, initial, hits);
      } else {
        for (unsigned m = lanes; m != 0; m &= m - 1) {
          const int k = __builtin_ctz(m);
          kernels.closest(tris, begin, end, rays[k], hits[k]);
          if (hits[k].t < tmax[k]) tmax[k] = hits[k].t;
        }
      }
      boxes.set_tmax(tmax);
      children.set_tmax(boxes.max_tmax(packet));
    }
    // pop, dropping entries that every one of their lanes has a nearer hit than
    for (;;) {
      if (sp == 0) return;
      --sp;
      if (stack[sp].t <= boxes.max_tmax(stack[sp].lanes)) break;
    }
    ref = stack[sp].ref;
    lanes = stack[sp].lanes;
  }
}

// A packet's rays as SoA rows: o (0..2), d (3..5), tmin (6), tmax (7); and 1/d.
struct PacketRows {
  alignas(64) float soa[8][pfloat::W];
  alignas(64) float rd[3][pfloat::W];
};

// Transposes rays[0..P) of the lanes `active` (the other rays not read) into `s` and forms 1/d.
// Returns the lanes left to trace: traceable rays (finite origin and direction, no NaN tmin or
// tmax, as bvh.cpp's single rays) that enter the root's box.
template <class PK>
RAYVEC_INLINE unsigned load_packet(const BvhArrays& bvh, const Ray* rays, unsigned active, PacketRows& s) {
  static_assert(sizeof(Ray) == 8 * sizeof(float), "PK::load_rays reads a Ray as 8 floats");
  active = PK::load_rays(reinterpret_cast<const float*>(rays), active, s.soa);
  if (active == 0) return 0;
  const pfloat one = pfloat::broadcast(1.0f);
  for (int a = 0; a < 3; ++a)  // ±0 gives ±inf with the sign of the zero, as 1.0f / d does
    (one / pfloat::load(s.soa[3 + a])).store(s.rd[a]);
  // Camera packets often miss the whole mesh (the background): the root's box (the union of its
  // children's, kept by WideBvh) first, one test instead of N, dropping the lanes that miss it.
  const pfloat o[3] = {pfloat::load(s.soa[0]), pfloat::load(s.soa[1]), pfloat::load(s.soa[2])};
  const pfloat r[3] = {pfloat::load(s.rd[0]), pfloat::load(s.rd[1]), pfloat::load(s.rd[2])};
  return packet_box_lanes(bvh.root_lo, bvh.root_hi, o, r, pfloat::load(s.soa[6]), pfloat::load(s.soa[7]),
                          bvh.box_epsilon, active);
}

// Calls traverse(boxes, children) with the box test the packet's lanes `active` allow.
//
// The forward test (PK::Forward) when every lane has tmin >= 0 and no slab product can overflow:
// |1/d| · max(|o|, |root box|) <= 2^120 on every axis of every lane (so also no infinite 1/d of a
// zero direction component, whose 0·inf the FMA form could not skip), and eps >= 2^-20.
//
// Why it never drops a box the general test keeps (u = 2^-24): r = fl(1/d) = (1/d)(1 + δ0) and
// r' = fl(r·(1 − eps)) = r(1 − eps)(1 + δ1); k >= o·r' exactly (PK::Forward::outward moves the
// rounded product up by more than its error). The FMA rounds once: t' = fl(b·r' − k) with
// b·r' − k <= (b − o)·r'. If the exact entry (b − o)/d > 0, t' <= (b − o)/d · (1 − eps)(1 + u)^3,
// below it by more than 0.9·eps·|t| as in the general and single-ray tests; if it is <= 0, so
// is t', and tmin >= 0 decides in both. The exit mirrors this with r·(1 + eps) and k rounded
// down: above the exact exit by more than 0.9·eps·|t| when it is > 0; an exact exit < 0 misses
// in both (tmin >= 0), and an exit of exactly 0 gives t' >= 0. Without the outward rounding the
// error of o·r' (u·|o·r'|, not relative to t) loses boxes far from the coordinate origin
// (tests/bvh/bvh_packet_box_test.cpp). The gain: benchmarks.md#decision-packet-setup. Packets whose
// lanes share the direction signs (uniform) also get the hull pre-test (PacketChildren).
template <class B, class PK, class Traverse>
RAYVEC_INLINE void with_packet_boxes(const BvhArrays& bvh, const PacketRows& s, unsigned active,
                                     const Traverse& traverse) {
  const float* const rows[8] = {s.soa[0], s.soa[1], s.soa[2], s.rd[0], s.rd[1], s.rd[2], s.soa[6], s.soa[7]};
  const pfloat zero = pfloat::broadcast(0.0f);
  const pfloat big = pfloat::broadcast(0x1p120f);
  pfloat m =
      vmax(vmax(abs(pfloat::load(s.soa[0])), abs(pfloat::load(s.soa[1]))), abs(pfloat::load(s.soa[2])));
  for (int a = 0; a < 3; ++a) m = vmax(m, pfloat::broadcast(vmax_abs(bvh.root_lo[a], bvh.root_hi[a])));
  const pfloat rd[3] = {pfloat::load(s.rd[0]), pfloat::load(s.rd[1]), pfloat::load(s.rd[2])};
  const pfloat r = vmax(vmax(abs(rd[0]), abs(rd[1])), abs(rd[2]));
  if (bvh.box_epsilon >= 0x1p-20f && (bits(pfloat::load(s.soa[6]) >= zero) & active) == active &&
      (bits(r * m <= big) & active) == active) {
    unsigned neg[3];  // lanes with a negative direction component; uniform: none or all
    bool uniform = true;
    for (int a = 0; a < 3; ++a) {
      neg[a] = bits(rd[a] < zero) & active;
      uniform = uniform && (neg[a] == 0 || neg[a] == active);
    }
    if (uniform) {
      auto boxes = PK::template Forward<true>::load(rows, neg, bvh.box_epsilon);
      const pfloat d[3] = {pfloat::load(s.soa[3]), pfloat::load(s.soa[4]), pfloat::load(s.soa[5])};
      // the hull built in place: a copy of its scalars, read back as vectors before their stores
      // have left, stalls (a braced list is evaluated in order: tmax is set before it is read)
      float tmax;
      PacketChildren<B, true> children{boxes.hull(rd, active, &tmax), tmax,
                                       slot_cull(bvh.packet_slot_cull, hmax_lanes(m, active), d, active)};
      traverse(boxes, children);
    } else {
      auto boxes = PK::template Forward<false>::load(rows, neg, bvh.box_epsilon);
      PacketChildren<B, false> children{};
      traverse(boxes, children);
    }
    return;
  }
  PacketBoxes<PK> boxes{PK::load(rows), bvh.box_epsilon};
  PacketChildren<B, false> children{};
  traverse(boxes, children);
}

// rays[0..P) with lanes `active`, the other lanes' rays not read: hits[k] of each active lane
// becomes its closest hit (a miss for an untraceable ray: NaN or infinite origin or direction, NaN
// tmin or tmax, as bvh.cpp's single rays).
template <class B, class PK>
void bvh_closest_packet(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                        const Ray* rays, Hit* hits, unsigned active) {
  constexpr int P = PK::P;
  static_assert(pfloat::W == P, "the packet leaf kernel has one ray per lane");
  // Streams of packets (closest_stream, tiles of a frame) lie one after the other: start loading
  // the rays and hits of the packet three ahead now, as the time of one packet is far too short
  // for the hardware to hide the memory latency of its first loads (benchmarks.md#decision-prefetch).
  // A prefetch never faults, so reaching past the end of the
  // caller's arrays is harmless (the addresses are formed as integers, not as pointers past them).
  const uintptr_t ahead_rays = reinterpret_cast<uintptr_t>(rays) + 3 * P * sizeof(Ray);
  const uintptr_t ahead_hits = reinterpret_cast<uintptr_t>(hits) + 3 * P * sizeof(Hit);
  for (uintptr_t j = 0; j < P * sizeof(Ray); j += 64)
    __builtin_prefetch(reinterpret_cast<const void*>(ahead_rays + j));
  for (uintptr_t j = 0; j < P * sizeof(Hit); j += 64)
    __builtin_prefetch(reinterpret_cast<const void*>(ahead_hits + j), 1);
  if (active == (1u << P) - 1u) {  // a full packet: P contiguous stores the compiler vectorizes
    for (int k = 0; k < P; ++k) hits[k] = Hit{};
  } else {
    for (unsigned m = active; m != 0; m &= m - 1) hits[__builtin_ctz(m)] = Hit{};
  }
  PacketRows s;  // tmax (row 7) becomes min(tmax, hit.t) per lane as hits are found
  active = load_packet<PK>(bvh, rays, active, s);
  if (active == 0) return;
  const pfloat zero = pfloat::broadcast(0.0f);
  const pfloat tmin0 = pfloat::load(s.soa[6]);
  const unsigned tmin_zero = bits((tmin0 >= zero) & (tmin0 <= zero));
  float* tmax = s.soa[7];

  // The leaf kernel: a packet kernel for this unit's float `mt` and `watertight` tables (the mt one
  // only when the lanes do not mix tmin = 0 with tmin != 0), else ray by ray.
  PacketLeaf leaf = PacketLeaf::ray_by_ray;
  if (kernels.isa == kThisIsa) {
    if (kernels.intersector == Intersector::mt) {
      if ((tmin_zero & active) == active)
        leaf = PacketLeaf::mt_tmin_zero;
      else if ((tmin_zero & active) == 0)
        leaf = PacketLeaf::mt;
    } else if (kernels.intersector == Intersector::watertight) {
      leaf = PacketLeaf::watertight;
    }
  }
  // formed in lanes (see bvh_occluded_packet)
  alignas(64) float initial[P];
  next_up(pfloat::load(tmax)).store(initial);
  const MtPacketRays<pfloat> q{
      {pfloat::load(s.soa[0]), pfloat::load(s.soa[1]), pfloat::load(s.soa[2]), pfloat::load(s.soa[3]),
       pfloat::load(s.soa[4]), pfloat::load(s.soa[5]), tmin0},
      leaf == PacketLeaf::mt ? mt_lower(tmin0) : zero};
  WatertightPacketRays<pfloat> wq;  // set only for the watertight leaf
  if (leaf == PacketLeaf::watertight) {
    const float* const o[3] = {s.soa[0], s.soa[1], s.soa[2]};
    const float* const d[3] = {s.soa[3], s.soa[4], s.soa[5]};
    set_watertight_packet_rays<pfloat>(wq, o, d, s.soa[6], active);
  }
  const PacketRun run{tmax, initial, leaf, q, wq};
  with_packet_boxes<B, PK>(
      bvh, s, active, [&](auto& boxes, auto& children) __attribute__((always_inline)) {
        bvh_packet_traverse<B, PK>(bvh, tris, kernels, rays, hits, active, boxes, children, run);
      });
}
