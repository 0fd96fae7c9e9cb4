// The packet leaves' slot cull (bvh/packet_slot_cull.inl): a uniform forward packet steps in a leaf
// only the triangles whose box, widened by the cull's margin, the hull of its lanes enters (and, for
// `mt`, every triangle its directions may graze). The cull must never change an answer. The packets
// here are sixteen copies of one ray, so the hull is that ray alone and the cull drops every triangle
// it can; their lanes must get exactly what the ray gets alone (closest: same id, bit-identical t, u,
// v; any hit: the same occlusion, with tmax at the hit and one step before it) — on the hard-case
// families, on rays that leave a surface at grazing angles, and on rays through the grid lines and
// grid points of a closed box made of axis-aligned squares (where a triangle's box has a face on the
// ray's path), near the coordinate origin and far from it; and with `watertight` every ray from
// inside the box must hit it. The cull is forced on (BvhOptions::packet_slot_cull), with `mt`'s
// normals stored and formed. Every ISA with packets this CPU has (the others are skipped and named),
// float `mt` and `watertight` (the intersectors with packet leaves).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "accel/bvh_accelerator.h"
#include "accuracy/hard_cases.h"
#include "bvh_cases.h"

namespace rayvec {
namespace {

class BvhPacketSlotCull : public test::BvhPacketCaseTest {
 protected:
  // The case's BVH with the cull on whatever the mesh's size and `mt`'s normals stored (1) or formed
  // per step (0) — the cull's grazing test reads the one or forms the other — or null for a mesh the
  // BVH refuses (a hard-case family with non-finite vertices).
  std::unique_ptr<BvhAccelerator> culling(const TriangleMesh& mesh, int stored_normals) const {
    BvhOptions options;
    options.width = GetParam().width;
    options.packet_slot_cull = 1;
    options.stored_normals = stored_normals;
    try {
      return std::make_unique<BvhAccelerator>(mesh, config(), options);
    } catch (const std::exception&) {
      return nullptr;
    }
  }
  // The normals to test: `watertight` reads none.
  std::vector<int> normals() const {
    return GetParam().intersector == Intersector::mt ? std::vector<int>{1, 0} : std::vector<int>{0};
  }
};

// Each ray as a packet of P copies of it.
std::vector<Ray> copies(const std::vector<Ray>& rays, int P) {
  std::vector<Ray> out;
  for (const Ray& r : rays)
    for (int k = 0; k < P; ++k) out.push_back(r);
  return out;
}

// Every lane of `packets` (P copies a ray) against its ray alone, closest hit and any hit (tmax as
// given, at the closest hit and one step before it). Returns the number of rays that hit.
int expect_copies_exact(const BvhAccelerator& a, const std::vector<Ray>& rays, const std::string& what) {
  auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
  const int P = a.traversal().packet_width;
  std::vector<Ray> any;  // the any-hit queries
  std::vector<Ray> packets = copies(rays, P);
  std::vector<Hit> hits(packets.size());
  a.closest_stream(packets.data(), hits.data(), packets.size());
  int hit = 0, wrong = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit want = a.closest(rays[i]);
    hit += want.hit();
    any.push_back(rays[i]);
    if (want.hit()) {
      Ray at = rays[i], before = rays[i];
      at.tmax = want.t;
      before.tmax = std::nextafter(want.t, -kInf);
      any.push_back(at);
      any.push_back(before);
    }
    for (int k = 0; k < P; ++k) {
      const Hit& got = hits[i * std::size_t(P) + std::size_t(k)];
      const bool same = got.tri == want.tri && bits(got.t) == bits(want.t) && bits(got.u) == bits(want.u) &&
                        bits(got.v) == bits(want.v);
      if (!same && ++wrong <= 3)
        ADD_FAILURE() << what << " ray " << i << " lane " << k << ": alone " << want.tri << " at " << want.t
                      << ", in a packet " << got.tri << " at " << got.t;
    }
  }
  packets = copies(any, P);
  std::vector<uint8_t> occluded(packets.size());
  a.occluded_stream(packets.data(), occluded.data(), packets.size(), nullptr);
  for (std::size_t i = 0; i < any.size(); ++i) {
    const bool want = a.occluded(any[i]);
    for (int k = 0; k < P; ++k)
      if (bool(occluded[i * std::size_t(P) + std::size_t(k)]) != want && ++wrong <= 3)
        ADD_FAILURE() << what << " any-hit query " << i << " lane " << k << ": alone " << want;
  }
  EXPECT_EQ(wrong, 0) << what << ": lanes unlike their ray alone";
  return hit;
}

TEST_P(BvhPacketSlotCull, SixteenCopiesOfEachHardCaseRayMatchTheRayAlone) {
  for (const int stored : normals()) {
    int families = 0;
    for (const HardCaseFamily& f : hard_case_families(11, 1)) {
      const std::unique_ptr<BvhAccelerator> accel = culling(f.mesh, stored);
      if (!accel) continue;
      expect_copies_exact(*accel, f.rays, f.name + (stored ? ", normals stored" : ""));
      ++families;
    }
    EXPECT_GE(families, 10);
  }
}

// Rays from points on the box's faces — inside a square, on a grid line, at a grid point — into the
// box at angles of 10^-1 to 10^-5 radians to the face, with tmin 0 and tmin just above: the triangles
// around the origin lie along the ray's first stretch, where rounding decides.
TEST_P(BvhPacketSlotCull, GrazingRaysLeavingAFaceMatchTheRayAlone) {
  for (const Vec3d centre : {Vec3d{0.2, -0.1, 0.3}, Vec3d{148376, 1234, -223423}}) {
    const double h = centre.x > 1000 ? 300.0 : 1.0;
    const int n = 8;
    const TriangleMesh box = grid_box(centre, h, n);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int r = 0; r < 300; ++r) {
      const int axis = r % 3;
      const double side = (r / 3) % 2 ? 1.0 : -1.0;
      double p[3] = {u(rng), u(rng), u(rng)};
      p[axis] = side;
      const int kind = r % 5;  // 0, 1: inside a square; 2, 3: on a grid line; 4: at a grid point
      const int pu = (axis + 1) % 3, pv = (axis + 2) % 3;
      if (kind >= 2) p[pu] = std::round(p[pu] * n / 2) * 2 / n;
      if (kind == 4) p[pv] = std::round(p[pv] * n / 2) * 2 / n;
      const Vec3f origin(centre + Vec3d{p[0], p[1], p[2]} * h);
      const double angle = std::pow(10.0, -1.0 - (r % 7) * 4.0 / 6.0);
      double d[3] = {u(rng), u(rng), 0.0};
      double dd[3];
      dd[pu] = d[0];
      dd[pv] = d[1];
      dd[axis] = -side * angle * std::hypot(d[0], d[1]);  // into the box
      const Vec3f dir{float(dd[0]), float(dd[1]), float(dd[2])};
      rays.push_back(Ray{origin, dir});  // on a grid line: two triangles tie at t = 0
      rays.push_back(Ray{origin, dir, float(1e-4 * h)});
    }
    for (const int stored : normals()) {
      const std::unique_ptr<BvhAccelerator> a = culling(box, stored);
      ASSERT_TRUE(a);
      EXPECT_GT(expect_copies_exact(*a, rays, "grazing, centre.x " + std::to_string(centre.x)), 300);
    }
  }
}

// Rays from inside the box through its grid lines and grid points, whose triangles' boxes have a
// face on the ray's path at the hit: every lane gets its ray's answer, and with `watertight` every
// ray hits.
TEST_P(BvhPacketSlotCull, RaysThroughGridLinesAndPointsOfAClosedBoxMatchTheRayAlone) {
  for (const Vec3d centre : {Vec3d{0.2, -0.1, 0.3}, Vec3d{148376, 1234, -223423}}) {
    const double h = centre.x > 1000 ? 300.0 : 1.0;
    const int n = 8;
    const TriangleMesh box = grid_box(centre, h, n);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int r = 0; r < 600; ++r) {
      const Vec3f origin(centre + Vec3d{u(rng), u(rng), u(rng)} * (0.7 * h));
      const int axis = r % 3, pu = (axis + 1) % 3, pv = (axis + 2) % 3;
      double p[3] = {u(rng), u(rng), u(rng)};
      p[axis] = (r / 3) % 2 ? 1.0 : -1.0;
      p[pu] = std::round(p[pu] * n / 2) * 2 / n;             // on a grid line
      if (r % 2) p[pv] = std::round(p[pv] * n / 2) * 2 / n;  // at a grid point
      const Vec3f target(centre + Vec3d{p[0], p[1], p[2]} * h);
      rays.push_back(Ray{origin, Vec3f(Vec3d(target) - Vec3d(origin))});
    }
    for (const int stored : normals()) {
      const std::unique_ptr<BvhAccelerator> a = culling(box, stored);
      ASSERT_TRUE(a);
      const int hits = expect_copies_exact(*a, rays, "grid lines, centre.x " + std::to_string(centre.x));
      if (GetParam().intersector == Intersector::watertight) {
        EXPECT_EQ(hits, int(rays.size()));
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsasWidths, BvhPacketSlotCull,
                         ::testing::ValuesIn(test::bvh_cases({Intersector::mt, Intersector::watertight})),
                         test::bvh_case_name);

}  // namespace
}  // namespace rayvec
