// Experiment: the mt float step with ONE mask-producing instruction for the whole pre-test. On Zen 5
// every instruction that writes a mask register (vcmpps, vptestnmd, vpmovd2m, vpcmpud) competes with
// the FMAs for the same two pipes, while adds, subtractions and bitwise ops have two/four pipes of
// their own. So the five ordered compares of mt_numerators become sign bits: u·|det|, v·|det|,
// t·|det| (−0 normalized to +0 by an add), (1 − u − v)·|det| and best·|det| − t·|det| must all have
// the sign bit clear — OR-ed (vpternlogd) and tested once (vptestnmd). NaN lanes may pass this
// pre-test; the exact stage (rare: ~6 of 3,125 steps per ray here) repeats the ordered compares.
#include <cstdint>
#include "kernels/kernel_table.h"
#include "kernels/simd/vfloat_avx512.h"
namespace rayvec::avx512 { namespace sgn {
#include "pinned_mt.inl"  // git show 96ea2dd:src/kernels/moller_trumbore.inl (build.sh)

// or3 and sign_clear: vfloat_avx512.h (added with row 11, which this variant prototyped)

template <bool TminZero>
RAYVEC_INLINE void step(const TriangleArrays& T, uint32_t i, const RayLanes<vfloat>& r, vmaskf active,
                        vfloat neg_lo, MtBest<vfloat>& b) {
  using V = vfloat;
  const V sx = V::load(T.v0x + slot_offset(i)) - r.ox, sy = V::load(T.v0y + slot_offset(i)) - r.oy, sz = V::load(T.v0z + slot_offset(i)) - r.oz;
  const V cx = fmsub(sy, r.dz, sz * r.dy), cy = fmsub(sz, r.dx, sx * r.dz), cz = fmsub(sx, r.dy, sy * r.dx);
  const V ngx = V::load(T.ngx + slot_offset(i)), ngy = V::load(T.ngy + slot_offset(i)), ngz = V::load(T.ngz + slot_offset(i));
  const V det = fmadd(r.dx, ngx, fmadd(r.dy, ngy, r.dz * ngz));
  const V sign = sign_bit(det), adet = abs(det), zero = V::broadcast(0.0f);
  const V e2x = V::load(T.e2x + slot_offset(i)), e2y = V::load(T.e2y + slot_offset(i)), e2z = V::load(T.e2z + slot_offset(i));
  const V un = xor_bits(fmadd(e2x, cx, fmadd(e2y, cy, e2z * cz)), sign);  // −u·|det|
  const V e1x = V::load(T.e1x + slot_offset(i)), e1y = V::load(T.e1y + slot_offset(i)), e1z = V::load(T.e1z + slot_offset(i));
  const V a = zero - un;                                                   // u·|det|, never −0
  const V bv = xor_bits(fmadd(e1x, cx, fmadd(e1y, cy, e1z * cz)), sign) + zero;  // v·|det|
  const V tn = xor_bits(fmadd(sx, ngx, fmadd(sy, ngy, sz * ngz)), sign) + zero;  // t·|det|
  const V w = adet - (a + bv);                                             // (1 − u − v)·|det|
  const V nearer = fmsub(b.hi, adet, tn);                                  // best·|det| − t·|det|
  const V low = TminZero ? tn : fmadd(neg_lo, adet, tn);                   // t·|det| − lo·|det|
  const vmaskf pre = sign_clear(or3(or3(a, bv, w), low, nearer)) & active;
  if (!any(pre)) return;
  const V t = tn / adet;
  const vmaskf m = pre & (a >= zero) & (bv >= zero) & (w >= zero) & (adet > zero) & (t >= r.tmin) & (t < b.t);
  if (!any(m)) return;
  b.t = select(m, b.t, t);
  b.un = select(m, b.un, un);
  b.vn = select(m, b.vn, bv);
  b.adet = select(m, b.adet, adet);
  b.idx = select(m, b.idx, V::index_bits(i));
  b.hi = V::broadcast(hmin(b.t) * kMtWiden);
  b.found = true;
}

template <bool TminZero, int R>
void rays_impl(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays, Hit* hits) {
  using V = vfloat;
  MtRay<V> q[R];
  V neg_lo[R];
  for (int k = 0; k < R; ++k) {
    q[k] = mt_ray<V>(rays[k], hits[k]);
    neg_lo[k] = V::broadcast(0.0f) - q[k].lo;
  }
  const vmaskf all = first_lanes(V{}, 16);
  uint32_t i = begin;
  for (; end - i >= 16u && i < end; i += 16)
    for (int k = 0; k < R; ++k) step<TminZero>(T, i, q[k].r, all, neg_lo[k], q[k].b);
  if (i < end)
    for (int k = 0; k < R; ++k) step<TminZero>(T, i, q[k].r, first_lanes(V{}, end - i), neg_lo[k], q[k].b);
  for (int k = 0; k < R; ++k) mt_finish<V>(T, q[k].b, q[k].initial, hits[k]);
}

void closest1(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray& ray, Hit& hit) {
  if (!finite_ray(ray)) return;
  if (ray.tmin == 0.0f) rays_impl<true, 1>(T, begin, end, &ray, &hit);
  else rays_impl<false, 1>(T, begin, end, &ray, &hit);
}
void closest2(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays, Hit* hits) {
  if (!finite_ray(rays[0]) || !finite_ray(rays[1])) {
    closest1(T, begin, end, rays[0], hits[0]);
    closest1(T, begin, end, rays[1], hits[1]);
    return;
  }
  if (rays[0].tmin == 0.0f && rays[1].tmin == 0.0f) rays_impl<true, 2>(T, begin, end, rays, hits);
  else rays_impl<false, 2>(T, begin, end, rays, hits);
}
void closest4(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays, Hit* hits) {
  rays_impl<true, 4>(T, begin, end, rays, hits);  // experiment only: finite rays with tmin = 0
}
const TriangleKernels kVar{Isa::avx512, Intersector::mt, 16, &closest1, nullptr, &closest2};
} }
namespace rayvec { const TriangleKernels& variant_kernels() { return avx512::sgn::kVar; }
void variant_quad(const TriangleArrays& T, uint32_t b, uint32_t e, const Ray* r, Hit* h) { avx512::sgn::closest4(T, b, e, r, h); } }
