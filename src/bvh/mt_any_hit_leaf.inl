// The any-hit traversal's leaves by this unit's float `mt` kernel called directly, with the ray's
// lanes, pre-test factors and exact bound broadcast once per ray (MtAnyHitRay, kept in memory)
// instead of at every leaf as the kernel table's entry must: a shadow ray visits a few leaves of a
// few triangles each, so that per-leaf setup weighed as much as the tests
// (benchmarks.md#decision-any-hit-leaf-lanes). Other tables go through the table. Same occlusion as
// the table's: the same kernel body, and the table entry's finite_ray test is already passed by every
// ray reaching a leaf (BvhAccelerator rejects the others). Included by the ISA units after
// single_ray_traversal.inl and kernels/mt_float.inl, where kThisIsa names the unit's ISA.

namespace {

// Out of line, reading the ray's lanes from memory: inlined, its registers would crowd the
// traversal loop's.
template <class V>
__attribute__((noinline)) bool occluded_mt_float_leaf(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                                      const MtAnyHitRay<V>& q, const HitFilter* filter) {
  return occluded_mt_float_lanes<V>(T, begin, end, q, filter);
}

template <class V>
struct MtAnyHitLeaf {
  MtAnyHitRay<V> q;
  const TriangleKernels& k;
  const Ray& ray;
  bool is_direct;
  RAYVEC_INLINE MtAnyHitLeaf(const TriangleKernels& kernels, const TriangleArrays&, const Ray& r)
      : q(mt_any_hit_ray<V>(r)),
        k(kernels),
        ray(r),
        is_direct(kernels.intersector == Intersector::mt && kernels.isa == kThisIsa) {}
  RAYVEC_INLINE bool occluded(const TriangleArrays& tris, uint32_t begin, uint32_t end,
                              const HitFilter* filter) const {
    if (!is_direct) return k.occluded(tris, begin, end, ray, filter);
    return occluded_mt_float_leaf<V>(tris, begin, end, q, filter);
  }
};

}  // namespace
