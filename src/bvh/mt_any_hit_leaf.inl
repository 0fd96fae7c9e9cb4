// The any-hit traversal's leaves by this unit's float `mt` kernel, inlined into the traversal loop,
// with the ray's lanes, pre-test factors and exact bound broadcast once per ray (MtAnyHitRay)
// instead of at every leaf as the kernel table's entry must: a shadow ray visits a few leaves of a
// few triangles each, so that per-leaf setup, and then the call itself, weighed as much as the tests
// (benchmarks.md#decision-any-hit-leaf-lanes). Other tables go through the table. Same occlusion as
// the table's: the same kernel body, and the table entry's finite_ray test is already passed by every
// ray reaching a leaf (BvhAccelerator rejects the others). Included by the ISA units after
// single_ray_traversal.inl and kernels/mt_float.inl, where kThisIsa names the unit's ISA.

namespace {

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
    return occluded_mt_float_lanes<V>(tris, begin, end, q, filter);
  }
};

}  // namespace
