// Single-ray traversal of a WideBvh, written once over a box-lanes type B (box_lanes_<isa>.h) and
// compiled per ISA: bvh_traversal_<isa>.cpp includes this inside namespace rayvec::<isa>, after that
// ISA's simd header. No std:: calls here (ISA units must not instantiate inline code shared with
// baseline units).
//
// Closest hit: children ordered front to back by entry distance, the nearest entered at once, the
// others pushed with their distance and dropped on pop once a hit is nearer (ordered traversal as in
// Wald et al. 2008 / Embree). Any hit: unordered, exits at the first accepted hit. Leaves call the
// triangle kernel table on their slot range, so results are those of brute force.
//
// Robust box test (after Ize 2013, "Robust BVH Ray Traversal"): t = (plane − o) · (1/d) computed as a
// subtraction then a multiplication, so each slab distance is within 3 ulps (γ3) of the exact value;
// the entry distance is then lowered and the exit raised by |t| · ε (bvh.box_epsilon, by default
// kDefaultBoxEpsilon = 2^-18, far above
// 2γ3 ≈ 3.6e-7) so no box that the exact ray touches is missed, with room for the rounding of the
// triangle kernels (a kernel may report t a few ulps outside the exact box). 1/d of a zero component
// is ±inf (IEEE), making the slab ±inf; when the origin lies on that plane 0·inf = NaN, and the
// NaN-skipping max/min chain ignores the slab (the ray runs inside the plane, which the closed box
// includes). Rays with a NaN or infinite origin or direction are rejected by the caller (bvh.cpp),
// as brute force never hits them either. Ties: a box whose entry equals the current hit distance is
// still entered, so a farther-in-order triangle at the same t with a lower id is found.
//
// Rays with tmin >= 0 (every ray of the renderer and the benchmarks) take the "forward" box test:
// the same widening folded into the reciprocals, entry distances with 1/d·(1 − ε) and exit
// distances with 1/d·(1 + ε), so a node costs no extra operation for it (Ize 2013 scales the exit
// reciprocal the same way). The computed slab distance is then within (1 ∓ ε)(1 ± u)^4 of the
// exact one (u = 2^-24), i.e. still widened by at least 0.9·|t|·ε. Scaling moves a negative
// distance toward zero instead of away from it, which only matters below tmin >= 0: a negative
// exit (the box is behind the origin; the sign of b − o is exact) misses either way, and a
// negative entry is replaced by tmin. Rays with tmin < 0 keep the per-node widening.

inline constexpr uint32_t kLocalStack = 256;

struct StackItem {
  uint32_t ref;
  float t;
};

// One ray's box test: robust for any tmin (Forward = false, widening per node) or for tmin >= 0
// (Forward = true, widening folded into the reciprocals).
template <class B, bool Forward>
struct RayBoxes;
template <class B>
struct RayBoxes<B, false> {
  typename B::RayData r;
  float eps;
  RAYVEC_INLINE unsigned hits(const float (*b)[B::N], float tmin, float tmax, float* dist) const {
    return B::hits(b, r, tmin, tmax, eps, dist);
  }
};
template <class B>
struct RayBoxes<B, true> {
  typename B::ForwardRay r;
  RAYVEC_INLINE unsigned hits(const float (*b)[B::N], float tmin, float tmax, float* dist) const {
    return B::hits_forward(b, r, tmin, tmax, dist);
  }
};

// Per-ray constants of the box test: 1/d and, per axis, the bounds row of the near plane.
template <class B, bool Forward>
RAYVEC_INLINE RayBoxes<B, Forward> ray_boxes(const Ray& ray, float eps) {
  const float o[3] = {ray.org.x, ray.org.y, ray.org.z};
  const float d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
  float rdir[3];
  int near[3];
  for (int a = 0; a < 3; ++a) {
    rdir[a] = 1.0f / d[a];  // ±0 gives ±inf with the sign of the zero
    near[a] = __builtin_signbit(d[a]) ? a + 3 : a;
  }
  if constexpr (Forward)
    return {B::prepare_forward(o, rdir, near, eps)};
  else
    return {B::prepare(o, rdir, near), eps};
}

RAYVEC_INLINE uint32_t leaf_begin(uint32_t ref) { return (ref >> 5) & (kMaxLeafBegin - 1); }
RAYVEC_INLINE uint32_t leaf_end(uint32_t ref) { return leaf_begin(ref) + (ref & 31u) + 1; }

// How the traversals intersect a leaf: through the kernel table (any intersector), or, where an ISA
// unit defines such a policy, by calling one of its float kernels directly (DirectMtLeaf in
// bvh_traversal_<isa>.cpp, WatertightLeaf in watertight_leaf.inl). All give the table's results.
// Each traversal makes one Leaf::Closest or Leaf::AnyHit per ray (what the ray's leaf calls need,
// formed once) and asks it about each leaf.
// What a leaf policy that needs only the kernel table and the ray keeps per ray.
struct LeafRay {
  const TriangleKernels& k;
  const Ray& ray;
  RAYVEC_INLINE LeafRay(const TriangleKernels& kernels, const TriangleArrays&, const Ray& r)
      : k(kernels), ray(r) {}
};

struct TableLeaf {
  struct Closest : LeafRay {
    using LeafRay::LeafRay;
    RAYVEC_INLINE void closest(const TriangleArrays& tris, uint32_t begin, uint32_t end, Hit& hit) const {
      k.closest(tris, begin, end, ray, hit);
    }
  };
  struct AnyHit : LeafRay {
    using LeafRay::LeafRay;
    RAYVEC_INLINE bool occluded(const TriangleArrays& tris, uint32_t begin, uint32_t end,
                                const HitFilter* filter) const {
      return k.occluded(tris, begin, end, ray, filter);
    }
  };
};

template <class B, bool Forward, class Leaf>
void bvh_closest_impl(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                      const Ray& ray, Hit& hit, uint32_t start) {
  constexpr int N = B::N;
  const WideNode<N>* nodes = static_cast<const WideNode<N>*>(bvh.nodes);
  const RayBoxes<B, Forward> boxes = ray_boxes<B, Forward>(ray, bvh.box_epsilon);
  StackItem local[kLocalStack];
  StackItem* stack = bvh.stack_size <= kLocalStack
                         ? local
                         : static_cast<StackItem*>(__builtin_alloca(bvh.stack_size * sizeof(StackItem)));
  uint32_t sp = 0;
  uint32_t ref = start;
  // tmin in a local: read through `ray` it is reloaded after every leaf (the leaf writes `hit`,
  // whose floats may alias the ray's)
  const float tmin = ray.tmin;
  float tmax = ray.tmax < hit.t ? ray.tmax : hit.t;
  const typename Leaf::Closest leaf(kernels, tris, ray);
  for (;;) {
    if (!(ref & kLeafFlag)) {
      const WideNode<N>& node = nodes[ref];
      alignas(64) float dist[N];
      unsigned mask = boxes.hits(node.bounds, tmin, tmax, dist);
      if (mask != 0) {
        const unsigned rest = mask & (mask - 1);
        if ((rest & (rest - 1)) == 0) {
          // one or two children hit (about three node visits in four): enter the nearer, push the
          // other. One path for both, without a branch between them: incoherent rays, whose paths
          // no predictor learns, often mispredicted it (benchmarks.md#decision-one-or-two-children).
          // With one child k0 = k1 and the entry written at the top is not pushed (the stack holds
          // one entry more than a traversal pushes). Ties enter the later child first, as the sort
          // below does.
          const unsigned k0 = unsigned(__builtin_ctz(mask)), k1 = 31u - unsigned(__builtin_clz(mask));
          const bool second_nearer = !(dist[k0] < dist[k1]);
          const unsigned far = second_nearer ? k0 : k1, nearer = second_nearer ? k1 : k0;
          stack[sp] = StackItem{node.ref[far], dist[far]};
          sp += rest != 0;
          ref = node.ref[nearer];
          continue;
        }
        // more: insertion sort straight onto the stack, farthest deepest (N is small), then enter
        // the nearest. Sorting in place keeps no per-child arrays live, so the loop's state (node
        // pointer, plane offsets, tmin) stays in registers instead of being spilled around a sort
        // (benchmarks.md#decision-sort-on-the-stack).
        const uint32_t base = sp;
        for (; mask != 0; mask &= mask - 1) {
          const unsigned k = unsigned(__builtin_ctz(mask));
          const float d = dist[k];
          uint32_t j = sp++;
          while (j > base && stack[j - 1].t < d) {  // descending: farthest first
            stack[j] = stack[j - 1];
            --j;
          }
          stack[j] = StackItem{node.ref[k], d};
        }
        ref = stack[--sp].ref;
        continue;
      }
    } else if (ref != kEmptyRef) {
      leaf.closest(tris, leaf_begin(ref), leaf_end(ref), hit);
      if (hit.t < tmax) tmax = hit.t;
    }
    // pop, dropping entries now behind the nearest hit
    for (;;) {
      if (sp == 0) return;
      --sp;
      if (stack[sp].t <= tmax) break;
    }
    ref = stack[sp].ref;
  }
}

// Closest hit in the subtree `start` (0 = the whole tree).
template <class B, class Leaf = TableLeaf>
RAYVEC_INLINE void bvh_closest_from(const BvhArrays& bvh, const TriangleArrays& tris,
                                    const TriangleKernels& kernels, const Ray& ray, Hit& hit,
                                    uint32_t start) {
  if (ray.tmin >= 0.0f)
    bvh_closest_impl<B, true, Leaf>(bvh, tris, kernels, ray, hit, start);
  else
    bvh_closest_impl<B, false, Leaf>(bvh, tris, kernels, ray, hit, start);
}

template <class B, class Leaf = TableLeaf>
void bvh_closest(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                 const Ray& ray, Hit& hit) {
  bvh_closest_from<B, Leaf>(bvh, tris, kernels, ray, hit, 0);
}

template <class B, bool Forward, class Leaf>
bool bvh_occluded_impl(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                       const Ray& ray, const HitFilter* filter, uint32_t start) {
  constexpr int N = B::N;
  const WideNode<N>* nodes = static_cast<const WideNode<N>*>(bvh.nodes);
  const RayBoxes<B, Forward> boxes = ray_boxes<B, Forward>(ray, bvh.box_epsilon);
  uint32_t local[kLocalStack];
  uint32_t* stack = bvh.stack_size <= kLocalStack
                        ? local
                        : static_cast<uint32_t*>(__builtin_alloca(bvh.stack_size * sizeof(uint32_t)));
  uint32_t sp = 0;
  uint32_t ref = start;
  // tmin and tmax in locals: read through `ray` they are reloaded after every leaf call
  const float tmin = ray.tmin, tmax = ray.tmax;
  const typename Leaf::AnyHit leaf(kernels, tris, ray);
  for (;;) {
    if (!(ref & kLeafFlag)) {
      const WideNode<N>& node = nodes[ref];
      alignas(64) float dist[N];
      unsigned mask = boxes.hits(node.bounds, tmin, tmax, dist);
      if (mask != 0) {
        ref = node.ref[__builtin_ctz(mask)];
        for (mask &= mask - 1; mask != 0; mask &= mask - 1) stack[sp++] = node.ref[__builtin_ctz(mask)];
        continue;
      }
    } else if (ref != kEmptyRef) {
      if (leaf.occluded(tris, leaf_begin(ref), leaf_end(ref), filter)) return true;
    }
    if (sp == 0) return false;
    ref = stack[--sp];
  }
}

// Any hit in the subtree `start` (0 = the whole tree).
template <class B, class Leaf = TableLeaf>
RAYVEC_INLINE bool bvh_occluded_from(const BvhArrays& bvh, const TriangleArrays& tris,
                                     const TriangleKernels& kernels, const Ray& ray, const HitFilter* filter,
                                     uint32_t start) {
  return ray.tmin >= 0.0f ? bvh_occluded_impl<B, true, Leaf>(bvh, tris, kernels, ray, filter, start)
                          : bvh_occluded_impl<B, false, Leaf>(bvh, tris, kernels, ray, filter, start);
}

template <class B, class Leaf = TableLeaf>
bool bvh_occluded(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                  const Ray& ray, const HitFilter* filter) {
  return bvh_occluded_from<B, Leaf>(bvh, tris, kernels, ray, filter, 0);
}
