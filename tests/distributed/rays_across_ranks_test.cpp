// How a distributed command shares its rays, and how its load is reported; a cluster of one traces
// everything itself.
#include <gtest/gtest.h>

#include "distributed/rank_loads.h"
#include "distributed/rays_across_ranks.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

TEST(ShareOf, SharesAreContiguousInRankOrderAndDifferByAtMostOne) {
  for (std::size_t n : {0, 1, 5, 7, 1000, 1001})
    for (int ranks : {1, 2, 3, 8}) {
      std::size_t next = 0, smallest = n, largest = 0;
      for (int r = 0; r < ranks; ++r) {
        const auto [first, last] = share_of(n, r, ranks);
        EXPECT_EQ(first, next) << n << " " << ranks;
        next = last;
        smallest = std::min(smallest, last - first);
        largest = std::max(largest, last - first);
      }
      EXPECT_EQ(next, n);
      EXPECT_LE(largest - smallest, 1u);
    }
}

TEST(RankLoads, ImbalanceIsTheSlowestOverTheMean) {
  RankLoads loads;
  EXPECT_EQ(loads.imbalance(), 0.0);
  loads.ranks = {{100, 3, 1, 1.0}, {50, 1, 1, 3.0}};
  EXPECT_DOUBLE_EQ(loads.imbalance(), 1.5);
  const std::string text = loads.text();
  EXPECT_NE(text.find("ranks: 2; rays per rank: 100, 50; tiles per rank (in ranges): 3 in 1, 1 in 1"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("load imbalance (slowest / mean): 1.500"), std::string::npos) << text;
}

TEST(RaysAcrossRanks, AClusterOfOneTracesEveryRay) {
  TriangleMesh mesh;
  mesh.add_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  const auto accel = make_accelerator(AccelKind::bvh, mesh, TraceConfig{});
  RayBatch rays;
  rays.push_back(Ray{{0, 0, -1}, {0, 0, 1}});
  rays.push_back(Ray{{5, 5, -1}, {0, 0, 1}});
  std::vector<Hit> hits;
  RankLoads loads;
  trace_closest_across_ranks(cluster(), *accel, rays, hits, loads);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].tri, 0);
  EXPECT_EQ(hits[1].tri, -1);
  ASSERT_EQ(loads.ranks.size(), 1u);
  EXPECT_EQ(loads.ranks[0].rays, 2u);
  std::vector<uint8_t> occluded;
  trace_occluded_across_ranks(cluster(), *accel, rays, occluded, loads);
  EXPECT_EQ(occluded, (std::vector<uint8_t>{1, 0}));
}

}  // namespace
}  // namespace rayvec
