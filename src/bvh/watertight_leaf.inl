// The single-ray traversals' leaves by this unit's float `watertight` kernels called directly, with
// the ray in ray space (WatertightRay: the axis permutation, the shear and the broadcast origin)
// formed once per ray instead of at every leaf, as the kernel table's entry must. A secondary ray
// of the renderer visits a few leaves of a few triangles each, so that per-leaf setup (three
// divisions and the permutation's branches) weighed as much as the triangle tests themselves.
// Results are the table's bit for bit: the same test_watertight steps in the same order, and the
// table entry's finite_ray test is already passed by every ray reaching a leaf (BvhAccelerator
// rejects the others). Included by the ISA units after single_ray_traversal.inl and kernels/watertight.inl.

namespace {

// One ray's leaf state: the ray in ray space, formed at the ray's first leaf, not before (rays that
// reach no leaf, most of a camera's background, would pay for it in vain), and the any-hit limit.
template <class V>
struct WatertightLeafRay {
  WatertightRay<V> r;
  V tlimit;
  bool formed = false;
};

template <class V>
RAYVEC_INLINE void form_once(WatertightLeafRay<V>& s, const TriangleArrays& T, const Ray& ray) {
  if (s.formed) return;
  s.r = watertight_ray<V>(T, ray);
  s.tlimit = watertight_any_limit<V>(ray);
  s.formed = true;
}

// The closest-hit leaf is called out of line: inlined into the traversal loop, its registers (and
// the ray's formation) would crowd the traversal's, except in large trees, whose rays wait on
// leaves from memory more than on the node steps' registers (LeafCall::inlined: WatertightLeaf<V,
// true>, benchmarks.md#decision-inlined-leaf). The any-hit leaf is always inlined: a shadow ray
// keeps no nearest hit and stops at its first, and the call cost more than the registers it spares
// (benchmarks.md#decision-any-hit-leaf-lanes).
template <class V>
RAYVEC_INLINE void watertight_closest_leaf_inline(const TriangleArrays& T, WatertightLeafRay<V>& s,
                                                  const Ray& ray, uint32_t begin, uint32_t end, Hit& hit) {
  form_once(s, T, ray);
  watertight_closest_ray<V>(T, s.r, begin, end, ray, hit);
}

template <class V>
__attribute__((noinline)) void watertight_closest_leaf(const TriangleArrays& T, WatertightLeafRay<V>& s,
                                                       const Ray& ray, uint32_t begin, uint32_t end,
                                                       Hit& hit) {
  watertight_closest_leaf_inline<V>(T, s, ray, begin, end, hit);
}

// Inlined: the closest-hit leaf inlined into the traversal loop too (the any-hit leaf always is).
template <class V, bool Inlined = false>
struct WatertightLeaf {
  struct Closest {
    const Ray& ray;
    mutable WatertightLeafRay<V> s;
    // inlined: zeroed first, or g++ cannot follow that form_once writes it before the kernel, inlined
    // into the traversal loop, reads it (-Wmaybe-uninitialized)
    RAYVEC_INLINE Closest(const TriangleKernels&, const TriangleArrays&, const Ray& q) : ray(q) {
      if constexpr (Inlined) s = WatertightLeafRay<V>{};
    }
    RAYVEC_INLINE void closest(const TriangleArrays& tris, uint32_t begin, uint32_t end, Hit& hit) const {
      if constexpr (Inlined)
        watertight_closest_leaf_inline<V>(tris, s, ray, begin, end, hit);
      else
        watertight_closest_leaf<V>(tris, s, ray, begin, end, hit);
    }
  };
  struct AnyHit {
    const Ray& ray;
    mutable WatertightLeafRay<V> s;
    // zeroed first, as the inlined Closest's (-Wmaybe-uninitialized)
    RAYVEC_INLINE AnyHit(const TriangleKernels&, const TriangleArrays&, const Ray& q) : ray(q) {
      s = WatertightLeafRay<V>{};
    }
    RAYVEC_INLINE bool occluded(const TriangleArrays& tris, uint32_t begin, uint32_t end,
                                const HitFilter* filter) const {
      form_once(s, tris, ray);
      return watertight_occluded_ray<V>(tris, s.r, s.tlimit, begin, end, filter);
    }
  };
};

}  // namespace
