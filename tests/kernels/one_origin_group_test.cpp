// The float `mt` group kernels for rays from one origin test each triangle step once for the whole
// group before any ray's own step runs (mt_float.inl): with the sign-bit tables, u·det and v·det
// come from the cross products e2 × s and e1 × s shared by the group, rounded otherwise than each
// ray's own numerators and widened by a bound on the difference (mt_crossed_slack). That test must
// never drop a hit a ray's own step finds. Rays from one origin aimed exactly at the vertices, edges
// and diagonals of a grid — where u, v or 1 − u − v is 0 up to rounding — must get bit for bit the
// hits and answers of one ray at a time: at unit scale, on a small grid far from the origin, near
// underflow, at a scale whose products could overflow (the group then tests ray by ray), with the
// origin in the grid's plane (t = 0) and with zero-area triangles among the grid's.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "kernels/closest_batch.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

struct GridCase {
  const char* name;
  float scale;      // the grid's side
  Vec3f offset;     // its corner
  Vec3f eye;        // the rays' origin, in units of the side from the corner
  float rise;       // the rays' targets lie this many sides above the grid (0: on it)
  bool degenerate;  // zero-area triangles between the grid's
};

constexpr int kCells = 6;

// A kCells × kCells grid of quads (two triangles each) in the plane z = offset.z.
TriangleMesh grid_mesh(const GridCase& c) {
  TriangleMesh mesh;
  const auto at = [&](int i, int j) {
    return Vec3f{c.offset.x + c.scale * float(i) / kCells, c.offset.y + c.scale * float(j) / kCells,
                 c.offset.z};
  };
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      mesh.add_triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      if (c.degenerate) mesh.add_triangle(at(i, j), at(i, j), at(i + 1, j + 1));
      mesh.add_triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return mesh;
}

// Rays from the case's eye at the grid's vertices, at points along its edges and diagonals, and at
// points inside cells; some with a finite tmax ending at the grid, some with tmin > 0.
std::vector<Ray> grid_rays(const GridCase& c) {
  const Vec3f eye = c.offset + c.eye * c.scale;
  std::vector<Ray> rays;
  const auto aim = [&](float a, float b) {
    const Vec3f target{c.offset.x + c.scale * a, c.offset.y + c.scale * b, c.offset.z + c.scale * c.rise};
    rays.push_back(Ray{eye, target - eye});
  };
  const float n = kCells;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      aim(float(i) / n, float(j) / n);                      // a vertex
      aim((float(i) + 0.37f) / n, float(j) / n);            // a horizontal edge
      aim(float(i) / n, (float(j) + 0.61f) / n);            // a vertical edge
      aim((float(i) + 0.43f) / n, (float(j) + 0.43f) / n);  // a diagonal
      aim((float(i) + 0.3f) / n, (float(j) + 0.6f) / n);    // inside a cell
    }
  for (std::size_t k = 0; k < rays.size(); ++k) {
    if (k % 7 == 3) rays[k].tmax = 1.0f;   // ends exactly at the grid
    if (k % 11 == 5) rays[k].tmin = 0.5f;  // starts half-way
  }
  return rays;
}

void expect_groups_match_one_ray_at_a_time(const TriangleKernels& k, const GridCase& c,
                                           const std::string& what) {
  const TriangleSoA soa(grid_mesh(c));
  const std::vector<Ray> rays = grid_rays(c);
  std::vector<Hit> batch(rays.size());
  closest_batch(k, soa.arrays(), 0, soa.size(), rays.data(), batch.data(), batch.size());
  std::vector<uint8_t> occluded(rays.size());
  occluded_batch(k, soa.arrays(), 0, soa.size(), rays.data(), occluded.data(), occluded.size(), nullptr);
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit one;
    k.closest(soa.arrays(), 0, soa.size(), rays[i], one);
    hits += one.hit();
    ASSERT_EQ(batch[i].tri, one.tri) << what << " ray " << i;
    if (one.hit()) {
      ASSERT_EQ(batch[i].t, one.t) << what << " ray " << i;
      ASSERT_EQ(batch[i].u, one.u) << what << " ray " << i;
      ASSERT_EQ(batch[i].v, one.v) << what << " ray " << i;
    }
    ASSERT_EQ(occluded[i], k.occluded(soa.arrays(), 0, soa.size(), rays[i], nullptr) ? 1 : 0)
        << what << " ray " << i;
  }
  EXPECT_GT(hits * 2, int(rays.size())) << what << ": most rays should hit the grid";
}

const GridCase kCases[] = {
    {"unit", 1.0f, {0, 0, 0}, {0.41f, 0.53f, 1.3f}, 0.0f, false},
    {"far and small", 1e-3f, {1e3f, -2e3f, 5e2f}, {-4e5f, 3e5f, 2e6f}, 0.0f, false},
    {"tiny", 1e-9f, {0, 0, 0}, {0.41f, 0.53f, 1.3f}, 0.0f, false},
    {"huge", 1e12f, {0, 0, 0}, {0.41f, 0.53f, 1.3f}, 0.0f, false},
    {"eye on a vertex, rays up", 1.0f, {0, 0, 0}, {0.5f, 0.5f, 0.0f}, 1.0f, false},
    {"eye inside a cell, rays down", 1.0f, {0, 0, 0}, {0.3f, 0.6f, 0.0f}, -1.0f, false},
    {"zero-area triangles", 1.0f, {0, 0, 0}, {0.41f, 0.53f, 1.3f}, 0.0f, true},
};

TEST(OneOriginGroups, EdgeAimedRaysGetTheHitsOfOneRayAtATime) {
  for (Isa isa : kAllIsas) {
    if (!isa_supported(isa)) {
      std::printf("[ skipped ] %s: this CPU lacks it\n", isa_name(isa));
      continue;
    }
    for (MtPretest pretest : {MtPretest::sign_bits, MtPretest::ordered_compares})
      for (const GridCase& c : kCases) {
        const std::string what = std::string(isa_name(isa)) +
                                 (pretest == MtPretest::sign_bits ? " sign" : " ordered") + " " + c.name;
        expect_groups_match_one_ray_at_a_time(triangle_kernels(isa, Intersector::mt, pretest), c, what);
      }
  }
}

}  // namespace
}  // namespace rayvec
