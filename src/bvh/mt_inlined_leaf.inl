// The closest-hit traversal's leaves by this unit's float `mt` single-ray kernel inlined into the
// traversal loop (LeafCall::inlined, the default for large trees: bvh_traversal.h,
// benchmarks.md#decision-inlined-leaf). Called out of line, the kernel costs each leaf a call, the
// kernel's prologue and the traversal's box constants saved to the stack and reloaded around it;
// where a ray's leaves come from memory (trees of many triangles) that overhead is worth more than
// the registers the inlined kernel takes from the node steps, which then reload a few constants from
// the stack. Other tables go through the table. Same hits as the called kernel: the same body
// (closest_mt_float_one_inline), and the table entry's finite_ray test is already passed by every ray
// reaching a leaf (BvhAccelerator rejects the others). Any hit: MtAnyHitLeaf. `watertight` inlines
// its leaf the same way (WatertightLeaf<V, true>). Included by the ISA units after
// mt_any_hit_leaf.inl, where kThisIsa names the unit's ISA.

namespace {

struct InlinedMtLeaf {
  struct Closest : LeafRay {
    using LeafRay::LeafRay;
    RAYVEC_INLINE void closest(const TriangleArrays& tris, uint32_t begin, uint32_t end, Hit& hit) const {
      if (k.intersector != Intersector::mt || k.isa != kThisIsa) return k.closest(tris, begin, end, ray, hit);
      if (ray.tmin == 0.0f)
        closest_mt_float_one_inline<vfloat, true>(tris, begin, end, ray, hit);
      else
        closest_mt_float_one_inline<vfloat, false>(tris, begin, end, ray, hit);
    }
  };
  using AnyHit = MtAnyHitLeaf<vfloat>;
};

}  // namespace
