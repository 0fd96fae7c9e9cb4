// The collapse rules of WideBvh: sah_node_cost() is the Σ of the wide nodes' box areas (recomputed
// here from the nodes), and the default rule keeps the tree of the lower cost of the two greedy
// collapses — on a set of trees where each rule wins somewhere, so a reversed or one-sided choice
// fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bvh/binary_bvh.h"
#include "bvh/wide_bvh.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

// Σ over nodes of the half area of the union of the node's child boxes, in float per node as
// BBox::half_area computes it.
template <int N>
double recomputed_cost(const WideBvh& bvh) {
  const auto* nodes = static_cast<const WideNode<N>*>(bvh.arrays().nodes);
  double sum = 0;
  for (uint32_t n = 0; n < bvh.node_count(); ++n) {
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = *std::min_element(nodes[n].bounds[a], nodes[n].bounds[a] + N);
      hi[a] = *std::max_element(nodes[n].bounds[a + 3], nodes[n].bounds[a + 3] + N);
    }
    const float ex = hi[0] - lo[0], ey = hi[1] - lo[1], ez = hi[2] - lo[2];
    sum += double(ex * ey + ey * ez + ez * ex);
  }
  return sum;
}

double cost_of(const BinaryBvh& bin, int width, CollapseRule rule) {
  const WideBvh bvh(bin, width, rule);
  const double expected = width == 4   ? recomputed_cost<4>(bvh)
                          : width == 8 ? recomputed_cost<8>(bvh)
                                       : recomputed_cost<16>(bvh);
  EXPECT_NEAR(bvh.sah_node_cost(), expected, 1e-9 * expected) << "width " << width;
  return bvh.sah_node_cost();
}

struct Case {
  std::string name;
  TriangleMesh mesh;
  SahConfig sah;
};

std::vector<Case> cases() {
  SahConfig wide_leaves;  // AVX-512's leaves: cost per block of 16, up to 32 triangles
  wide_leaves.leaf_block = 16;
  wide_leaves.max_leaf = 32;
  std::vector<Case> c;
  c.push_back({"soup", test::random_soup(6000, 0.05f, 3), {}});
  c.push_back({"soup, 16-triangle blocks", test::random_soup(6000, 0.05f, 3), wide_leaves});
  c.push_back({"sphere", test::sphere(1.0f, 48, 96), {}});
  c.push_back({"sphere, 16-triangle blocks", test::sphere(1.0f, 48, 96), wide_leaves});
  c.push_back({"grid", test::flat_grid(60), {}});
  c.push_back({"grid, 16-triangle blocks", test::flat_grid(60), wide_leaves});
  return c;
}

TEST(CollapseRule, SahNodeCostIsTheSumOfTheNodeBoxAreas) {
  const BinaryBvh bin = build_binned_sah(test::sphere(2.0f, 20, 40));
  for (int width : {4, 8, 16})
    for (CollapseRule rule :
         {CollapseRule::largest_area, CollapseRule::most_triangles, CollapseRule::lower_sah_cost})
      EXPECT_GT(cost_of(bin, width, rule), 0.0);
}

TEST(CollapseRule, DefaultKeepsTheTreeOfLowerSahNodeCost) {
  int area_wins = 0, count_wins = 0;
  for (const Case& c : cases()) {
    const BinaryBvh bin = build_binned_sah(c.mesh, c.sah);
    for (int width : {4, 8, 16}) {
      const double area = cost_of(bin, width, CollapseRule::largest_area);
      const double count = cost_of(bin, width, CollapseRule::most_triangles);
      const double kept = cost_of(bin, width, CollapseRule::lower_sah_cost);
      EXPECT_EQ(kept, std::min(area, count)) << c.name << ", width " << width;
      area_wins += area < count;
      count_wins += count < area;
    }
  }
  // the cases must exercise both sides of the choice
  EXPECT_GT(area_wins, 0);
  EXPECT_GT(count_wins, 0);
}

}  // namespace
}  // namespace rayvec
