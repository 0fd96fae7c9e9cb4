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

inline constexpr uint32_t kLocalStack = 256;

struct StackItem {
  uint32_t ref;
  float t;
};

// Per-ray constants of the box test: 1/d and, per axis, the bounds row of the near plane.
template <class B>
RAYVEC_INLINE typename B::RayData box_ray(const Ray& ray) {
  const float o[3] = {ray.org.x, ray.org.y, ray.org.z};
  const float d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
  float rdir[3];
  int near[3];
  for (int a = 0; a < 3; ++a) {
    rdir[a] = 1.0f / d[a];  // ±0 gives ±inf with the sign of the zero
    near[a] = __builtin_signbit(d[a]) ? a + 3 : a;
  }
  return B::prepare(o, rdir, near);
}

RAYVEC_INLINE uint32_t leaf_begin(uint32_t ref) { return (ref >> 5) & (kMaxLeafBegin - 1); }
RAYVEC_INLINE uint32_t leaf_end(uint32_t ref) { return leaf_begin(ref) + (ref & 31u) + 1; }

// Closest hit in the subtree `start` (0 = the whole tree).
template <class B>
RAYVEC_INLINE void bvh_closest_from(const BvhArrays& bvh, const TriangleArrays& tris,
                                    const TriangleKernels& kernels, const Ray& ray, Hit& hit,
                                    uint32_t start) {
  constexpr int N = B::N;
  const WideNode<N>* nodes = static_cast<const WideNode<N>*>(bvh.nodes);
  const typename B::RayData r = box_ray<B>(ray);
  StackItem local[kLocalStack];
  StackItem* stack = bvh.stack_size <= kLocalStack
                         ? local
                         : static_cast<StackItem*>(__builtin_alloca(bvh.stack_size * sizeof(StackItem)));
  uint32_t sp = 0;
  uint32_t ref = start;
  float tmax = ray.tmax < hit.t ? ray.tmax : hit.t;
  for (;;) {
    if (!(ref & kLeafFlag)) {
      const WideNode<N>& node = nodes[ref];
      alignas(64) float dist[N];
      unsigned mask = B::hits(node.bounds, r, ray.tmin, tmax, bvh.box_epsilon, dist);
      if (mask != 0) {
        const unsigned first = unsigned(__builtin_ctz(mask));
        mask &= mask - 1;
        if (mask == 0) {  // one child: enter it
          ref = node.ref[first];
          continue;
        }
        // several: sort by entry distance (insertion sort, N is small), push all but the nearest
        uint32_t refs[N];
        float ts[N];
        int count = 1;
        refs[0] = node.ref[first];
        ts[0] = dist[first];
        for (; mask != 0; mask &= mask - 1) {
          const unsigned k = unsigned(__builtin_ctz(mask));
          int j = count++;
          while (j > 0 && ts[j - 1] < dist[k]) {  // descending: farthest first
            refs[j] = refs[j - 1];
            ts[j] = ts[j - 1];
            --j;
          }
          refs[j] = node.ref[k];
          ts[j] = dist[k];
        }
        for (int j = 0; j < count - 1; ++j) stack[sp++] = StackItem{refs[j], ts[j]};
        ref = refs[count - 1];
        continue;
      }
    } else if (ref != kEmptyRef) {
      kernels.closest(tris, leaf_begin(ref), leaf_end(ref), ray, hit);
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

template <class B>
void bvh_closest(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                 const Ray& ray, Hit& hit) {
  bvh_closest_from<B>(bvh, tris, kernels, ray, hit, 0);
}

template <class B>
bool bvh_occluded(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                  const Ray& ray, const HitFilter* filter) {
  constexpr int N = B::N;
  const WideNode<N>* nodes = static_cast<const WideNode<N>*>(bvh.nodes);
  const typename B::RayData r = box_ray<B>(ray);
  uint32_t local[kLocalStack];
  uint32_t* stack = bvh.stack_size <= kLocalStack
                        ? local
                        : static_cast<uint32_t*>(__builtin_alloca(bvh.stack_size * sizeof(uint32_t)));
  uint32_t sp = 0;
  uint32_t ref = 0;
  for (;;) {
    if (!(ref & kLeafFlag)) {
      const WideNode<N>& node = nodes[ref];
      alignas(64) float dist[N];
      unsigned mask = B::hits(node.bounds, r, ray.tmin, ray.tmax, bvh.box_epsilon, dist);
      if (mask != 0) {
        ref = node.ref[__builtin_ctz(mask)];
        for (mask &= mask - 1; mask != 0; mask &= mask - 1)
          stack[sp++] = node.ref[__builtin_ctz(mask)];
        continue;
      }
    } else if (ref != kEmptyRef) {
      if (kernels.occluded(tris, leaf_begin(ref), leaf_end(ref), ray, filter)) return true;
    }
    if (sp == 0) return false;
    ref = stack[--sp];
  }
}
