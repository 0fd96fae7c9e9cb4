// Exact ray–triangle oracle. The only includer of gmpxx.h.
//
// The exact test is Möller–Trumbore (Möller & Trumbore 1997) evaluated in rationals, where it has no
// rounding at all: det = e1·(d×e2), u·det = s·(d×e2), v·det = d·(s×e1), t·det = e2·(s×e1), with the
// sign of det folded in. Before it, a double-precision filter discards clear misses: each quantity
// is computed in double together with its "permanent" (the same expression over absolute values,
// with |a|+|b| standing for |a−b|); the rounding error of such a short expression is below
// ~10 ulps of the permanent, so a value beyond 1e-12·permanent has its sign for certain
// (Shewchuk 1997 style static filter, with a very generous constant).
#include "accuracy/exact_oracle.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>

#include "geometry/triangle_mesh.h"

namespace rayvec {

namespace {

using Q = mpq_class;
using Vec3q = Vec3<Q>;

bool finite(Vec3f v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

Vec3q exact(Vec3f v) { return {Q(double(v.x)), Q(double(v.y)), Q(double(v.z))}; }

Vec3q qcross(const Vec3q& a, const Vec3q& b) {
  return {Q(a.y * b.z - a.z * b.y), Q(a.z * b.x - a.x * b.z), Q(a.x * b.y - a.y * b.x)};
}
Q qdot(const Vec3q& a, const Vec3q& b) { return Q(a.x * b.x + a.y * b.y + a.z * b.z); }

// Filter verdict: a certain miss, or "ask the exact test".
bool certainly_misses(const Ray& r, Vec3f a, Vec3f b, Vec3f c) {
  const Vec3d o(r.org), d(r.dir), v0(a), v1(b), v2(c);
  const Vec3d e1 = v1 - v0, e2 = v2 - v0, s = o - v0;
  auto absv = [](Vec3d v) { return Vec3d{std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; };
  const Vec3d pe1 = absv(v1) + absv(v0), pe2 = absv(v2) + absv(v0), ps = absv(o) + absv(v0);
  const Vec3d pd = absv(d);
  const Vec3d h = cross(d, e2), q = cross(s, e1);
  // permanents of the cross products: |a|×|b| with + in place of −
  auto pcross = [](Vec3d x, Vec3d y) {
    return Vec3d{x.y * y.z + x.z * y.y, x.z * y.x + x.x * y.z, x.x * y.y + x.y * y.x};
  };
  const Vec3d ph = pcross(pd, pe2), pq = pcross(ps, pe1);
  const double det = dot(e1, h), un = dot(s, h), vn = dot(d, q);
  const double bdet = 1e-12 * dot(pe1, ph), bun = 1e-12 * dot(ps, ph), bvn = 1e-12 * dot(pd, pq);
  if (!(std::fabs(det) > bdet)) return false;  // det's sign unknown (or zero): exact test decides
  const double sg = det > 0 ? 1.0 : -1.0;
  const double u = sg * un, v = sg * vn, w = std::fabs(det) - u - v;
  return u < -bun || v < -bvn || w < -(bdet + bun + bvn);
}

}  // namespace

bool ExactHit::is_nearest(int32_t id) const { return std::binary_search(nearest.begin(), nearest.end(), id); }

// Exact test; on a hit stores the exact t in *t_out.
static bool exact_test(const Ray& r, Vec3f a, Vec3f b, Vec3f c, Q* t_out) {
  if (!finite(r.org) || !finite(r.dir) || !finite(a) || !finite(b) || !finite(c)) return false;
  if (std::isnan(r.tmin) || std::isnan(r.tmax) || r.tmin == kInf || r.tmax == -kInf) return false;
  if (certainly_misses(r, a, b, c)) return false;
  const Vec3q o = exact(r.org), d = exact(r.dir), v0 = exact(a);
  const Vec3q e1 = exact(b) - v0, e2 = exact(c) - v0, s = o - v0;
  const Vec3q h = qcross(d, e2), q = qcross(s, e1);
  Q det = qdot(e1, h);
  const int sg = sgn(det);
  if (sg == 0) return false;  // parallel ray or zero-area triangle
  Q un = qdot(s, h), vn = qdot(d, q), tn = qdot(e2, q);
  if (sg < 0) {
    det = -det;
    un = -un;
    vn = -vn;
    tn = -tn;
  }
  // edge tests (closed)
  if (sgn(un) < 0 || sgn(vn) < 0 || Q(un + vn) > det) return false;
  // depth test (closed window)
  Q t = tn / det;
  if (std::isfinite(r.tmin) && t < Q(double(r.tmin))) return false;
  if (std::isfinite(r.tmax) && t > Q(double(r.tmax))) return false;
  if (t_out) *t_out = std::move(t);
  return true;
}

bool exact_hits_triangle(const Ray& ray, Vec3f v0, Vec3f v1, Vec3f v2, double* t) {
  Q tq;
  if (!exact_test(ray, v0, v1, v2, t ? &tq : nullptr)) return false;
  if (t) *t = tq.get_d();
  return true;
}

struct ExactOracle::Impl {
  std::vector<Vec3f> a, b, c;  // the vertices of every triangle, by id
};

ExactOracle::ExactOracle(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    impl_->a.push_back(mesh.vertex(i, 0));
    impl_->b.push_back(mesh.vertex(i, 1));
    impl_->c.push_back(mesh.vertex(i, 2));
  }
}
ExactOracle::~ExactOracle() = default;
ExactOracle::ExactOracle(ExactOracle&&) noexcept = default;
ExactOracle& ExactOracle::operator=(ExactOracle&&) noexcept = default;

ExactHit ExactOracle::closest(const Ray& ray) const {
  ExactHit out;
  Q best, t;
  const Impl& m = *impl_;
  for (std::size_t i = 0; i < m.a.size(); ++i) {
    if (!exact_test(ray, m.a[i], m.b[i], m.c[i], &t)) continue;
    const int32_t id = int32_t(i);
    if (out.tri < 0 || t < best) {
      best = t;
      out.tri = id;
      out.nearest.assign(1, id);
    } else if (t == best) {
      out.nearest.push_back(id);  // ids ascend: the first stays the lowest
    }
  }
  if (out.hit()) out.t = best.get_d();
  return out;
}

bool ExactOracle::hits(const Ray& ray, int32_t tri) const {
  const Impl& m = *impl_;
  if (tri < 0 || std::size_t(tri) >= m.a.size()) return false;
  return exact_test(ray, m.a[tri], m.b[tri], m.c[tri], nullptr);
}

}  // namespace rayvec
