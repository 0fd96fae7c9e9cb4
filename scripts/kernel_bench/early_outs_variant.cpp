// Experiment: the new mt path with the paper's early-outs (a branch after u, after v, then depth).
#include <cstdint>
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx512.h"
namespace rayvec::avx512 { namespace var {
#include "pinned_mt.inl"  // git show 96ea2dd:src/kernels/moller_trumbore.inl (build.sh)
template <class V>
RAYVEC_INLINE void step_early(const TriangleArrays& T, uint32_t i, const RayLanes<V>& r, MtBest<V>& b) {
  const V sx = V::load(T.v0x + slot_offset(i)) - r.ox, sy = V::load(T.v0y + slot_offset(i)) - r.oy, sz = V::load(T.v0z + slot_offset(i)) - r.oz;
  const V cx = fmsub(sy, r.dz, sz * r.dy), cy = fmsub(sz, r.dx, sx * r.dz), cz = fmsub(sx, r.dy, sy * r.dx);
  const V ngx = V::load(T.ngx + slot_offset(i)), ngy = V::load(T.ngy + slot_offset(i)), ngz = V::load(T.ngz + slot_offset(i));
  const V det = fmadd(r.dx, ngx, fmadd(r.dy, ngy, r.dz * ngz));
  const V sign = sign_bit(det), adet = abs(det), zero = V::broadcast(0.0f);
  const V un = xor_bits(fmadd(V::load(T.e2x + slot_offset(i)), cx, fmadd(V::load(T.e2y + slot_offset(i)), cy, V::load(T.e2z + slot_offset(i)) * cz)), xor_bits(sign, V::broadcast(-0.0f)));
  auto m = (un >= zero) & (un <= adet);
  if (!any(m)) return;
  const V vn = xor_bits(fmadd(V::load(T.e1x + slot_offset(i)), cx, fmadd(V::load(T.e1y + slot_offset(i)), cy, V::load(T.e1z + slot_offset(i)) * cz)), sign);
  m = m & (vn >= zero) & (un + vn <= adet);
  if (!any(m)) return;
  const V tn = xor_bits(fmadd(sx, ngx, fmadd(sy, ngy, sz * ngz)), sign);
  m = m & (tn >= zero) & (tn < b.hi * adet);
  if (!any(m)) return;
  const V t = tn / adet;
  m = m & (t >= r.tmin) & (t < b.t);
  if (!any(m)) return;
  b.t = select(m, b.t, t); b.un = select(m, b.un, un); b.vn = select(m, b.vn, vn); b.adet = select(m, b.adet, adet);
  b.idx = select(m, b.idx, V::index_bits(i)); b.hi = V::broadcast(hmin(b.t) * kMtWiden); b.found = true;
}
template <class V>
void closest_early(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  MtRay<V> q = mt_ray<V>(ray, hit);
  for (uint32_t i = begin; i + 16 <= end; i += 16) step_early<V>(T, i, q.r, q.b);  // sizes are multiples of 16 here
  mt_finish<V>(T, q.b, q.initial, hit);
}
const TriangleKernels kVar{Isa::avx512, Intersector::mt, 16, &closest_early<vfloat>, nullptr};
} }
namespace rayvec { const TriangleKernels& variant_kernels() { return avx512::var::kVar; } }
