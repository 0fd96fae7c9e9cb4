// Ear clipping in the plane of the polygon's Newell normal, in double (float corners, their
// differences and products exact or nearly so), over a ring of the corners not yet clipped.
#include "scene/polygon_triangulation.h"

#include <cmath>

namespace rayvec {
namespace {

// The sum of the corners' edge terms (Newell's method), relative to the first corner: for a planar
// polygon its normal with length twice the area, pointing to the side from which the corners run
// counter-clockwise; for any other, the normal of the plane that best fits it.
Vec3d newell_normal(std::span<const Vec3f> p) {
  Vec3d n{};
  const Vec3d origin(p[0]);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d a = Vec3d(p[i]) - origin, b = Vec3d(p[(i + 1) % p.size()]) - origin;
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

struct Point2 {
  double u, v;
  friend bool operator==(Point2 a, Point2 b) { return a.u == b.u && a.v == b.v; }
};

// Twice the signed area of the triangle a b c: positive when it turns counter-clockwise.
double orient(Point2 a, Point2 b, Point2 c) { return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u); }

// The corners projected along the normal's largest axis, the two others ordered so that the
// polygon runs counter-clockwise (positive area).
std::vector<Point2> project(std::span<const Vec3f> p, const Vec3d& n) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const int drop = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  int u = (drop + 1) % 3, v = (drop + 2) % 3;  // (y,z), (z,x), (x,y): right-handed about `drop`
  if (n[drop] < 0) std::swap(u, v);
  std::vector<Point2> q(p.size());
  const Vec3d origin(p[0]);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d d = Vec3d(p[i]) - origin;
    q[i] = {d[u], d[v]};
  }
  return q;
}

// Ear clipping of the counter-clockwise ring q. An ear is a corner that does not turn clockwise
// and whose triangle with its two neighbours holds no reflex corner of the ring, inside or on its
// edges, other than copies of its own three points (the doubled corners of a bridge to a hole). A
// simple polygon always has one; when none is found in a whole turn of the ring (a polygon that
// crosses itself) the first corner that does not turn clockwise is clipped anyway, or else the
// current one. Once no reflex corner remains the rest is convex and becomes a fan.
class EarClipper {
 public:
  explicit EarClipper(std::vector<Point2> q) : q_(std::move(q)), prev_(q_.size()), next_(q_.size()) {
    const auto n = static_cast<uint32_t>(q_.size());
    for (uint32_t i = 0; i < n; ++i) {
      prev_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
    }
    reflex_.resize(n);
    for (uint32_t i = 0; i < n; ++i) update_reflex(i);
  }

  void run(std::vector<std::array<uint32_t, 3>>& out) {
    uint32_t remaining = static_cast<uint32_t>(q_.size());
    uint32_t at = 0, failed = 0;
    while (remaining > 3 && reflex_count_ > 0) {
      if (is_ear(at)) {
        at = clip(at, out);
        --remaining;
        failed = 0;
      } else if (++failed >= remaining) {
        at = clip(fallback_corner(at), out);
        --remaining;
        failed = 0;
      } else {
        at = next_[at];
      }
    }
    // convex (or a triangle) from here: a fan around `at`
    for (uint32_t b = next_[at]; next_[b] != at; b = next_[b]) out.push_back({at, b, next_[b]});
  }

 private:
  bool turns_clockwise(uint32_t i) const { return orient(q_[prev_[i]], q_[i], q_[next_[i]]) < 0; }

  void update_reflex(uint32_t i) {
    const bool now = turns_clockwise(i);
    reflex_count_ += int(now) - int(bool(reflex_[i]));
    reflex_[i] = now;
  }

  bool is_ear(uint32_t b) const {
    if (reflex_[b]) return false;
    const uint32_t a = prev_[b], c = next_[b];
    const Point2 pa = q_[a], pb = q_[b], pc = q_[c];
    for (uint32_t j = next_[c]; j != a; j = next_[j]) {
      if (!reflex_[j]) continue;
      const Point2 pj = q_[j];
      if (pj == pa || pj == pb || pj == pc) continue;
      if (orient(pa, pb, pj) >= 0 && orient(pb, pc, pj) >= 0 && orient(pc, pa, pj) >= 0) return false;
    }
    return true;
  }

  uint32_t fallback_corner(uint32_t at) const {
    uint32_t i = at;
    do {
      if (!reflex_[i]) return i;
      i = next_[i];
    } while (i != at);
    return at;
  }

  // Emits the ear at b, unlinks b, and returns the corner to look at next.
  uint32_t clip(uint32_t b, std::vector<std::array<uint32_t, 3>>& out) {
    const uint32_t a = prev_[b], c = next_[b];
    out.push_back({a, b, c});
    next_[a] = c;
    prev_[c] = a;
    if (reflex_[b]) --reflex_count_;
    reflex_[b] = false;
    update_reflex(a);
    update_reflex(c);
    return a;
  }

  std::vector<Point2> q_;
  std::vector<uint32_t> prev_, next_;
  std::vector<char> reflex_;
  int reflex_count_ = 0;
};

}  // namespace

bool quad_splits_at_0_2(const std::array<Vec3f, 4>& q) {
  const Vec3d n = newell_normal(q);
  int reflex = -1, reflex_corners = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3d in = Vec3d(q[i]) - Vec3d(q[(i + 3) % 4]), out = Vec3d(q[(i + 1) % 4]) - Vec3d(q[i]);
    if (dot(cross(in, out), n) < 0) {
      reflex = i;
      ++reflex_corners;
    }
  }
  if (reflex_corners == 1) return reflex % 2 == 0;
  const Vec3f e02 = q[2] - q[0], e13 = q[3] - q[1];
  const float sqr02 = e02.x * e02.x + e02.y * e02.y + e02.z * e02.z;
  const float sqr13 = e13.x * e13.x + e13.y * e13.y + e13.z * e13.z;
  return sqr02 < sqr13;
}

void triangulate_polygon(std::span<const Vec3f> p, std::vector<std::array<uint32_t, 3>>& out) {
  const auto n = static_cast<uint32_t>(p.size());
  if (n < 3) return;
  if (n == 3) {
    out.push_back({0, 1, 2});
    return;
  }
  if (n == 4) {
    if (quad_splits_at_0_2({p[0], p[1], p[2], p[3]})) {
      out.push_back({0, 1, 2});
      out.push_back({0, 2, 3});
    } else {
      out.push_back({0, 1, 3});
      out.push_back({1, 2, 3});
    }
    return;
  }
  const Vec3d normal = newell_normal(p);
  if (!(dot(normal, normal) > 0) || !std::isfinite(dot(normal, normal))) {
    for (uint32_t i = 1; i + 1 < n; ++i) out.push_back({0, i, i + 1});  // no plane: a fan
    return;
  }
  EarClipper(project(p, normal)).run(out);
}

}  // namespace rayvec
