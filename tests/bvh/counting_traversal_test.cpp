// The counting traversal (bvh/counting_traversal.h) behind the cost AOV: the same hits as the
// uncounted BVH queries at every node width, and counts that follow the work — one node for a ray
// that misses the root box, more nodes and triangles for rays into the mesh, brute force counting
// every triangle.
#include <gtest/gtest.h>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

TEST(CountingTraversal, SameHitsAsTheUncountedQueriesAtEveryWidth) {
  const TriangleMesh mesh = test::random_soup(3000, 0.2f, 5);
  const std::vector<Ray> rays = test::random_rays(2000, 2.0f, 9);
  for (Isa isa : {Isa::scalar, best_isa()})
    for (int k = 0; k < bvh_widths(isa).count; ++k) {
      const int width = bvh_widths(isa).widths[k];
      BvhOptions options;
      options.width = width;
      const TraceConfig config{isa, Intersector::mt};
      const BvhAccelerator bvh(mesh, config, options);
      TraversalCost total;
      for (const Ray& r : rays) {
        TraversalCost c;
        const Hit a = bvh.closest(r), b = bvh.closest_counted(r, c);
        ASSERT_EQ(a.tri, b.tri) << isa_name(isa) << " width " << width;
        ASSERT_EQ(a.t, b.t);
        EXPECT_GE(c.nodes, 1u);  // the root's boxes are always tested
        EXPECT_LE(c.triangles, bvh.triangles().size());
        TraversalCost o;
        ASSERT_EQ(bvh.occluded(r), bvh.occluded_counted(r, o));
        EXPECT_LE(o.nodes, c.nodes + bvh.tree().arrays().node_count);
        total += c;
      }
      EXPECT_GT(total.triangles, 0u);
      EXPECT_LT(total.triangles, uint64_t(rays.size()) * mesh.size() / 4)
          << "the BVH should cull most triangles";
    }
}

TEST(CountingTraversal, ARayPastTheMeshTestsOneNodeAndNoTriangle) {
  // Large enough that no node width makes the root's children all leaves (on a 16-wide tree with
  // merged leaves a thousand triangles fit under the root alone).
  const TriangleMesh mesh = test::sphere(1.0f, 64, 128);
  const BvhAccelerator bvh(mesh, TraceConfig{best_isa(), Intersector::mt});
  TraversalCost c;
  EXPECT_FALSE(bvh.closest_counted(Ray{{10, 10, 10}, {1, 0, 0}, 0.0f, kInf}, c).hit());
  EXPECT_EQ(c.nodes, 1u);
  EXPECT_EQ(c.triangles, 0u);
  TraversalCost into;
  EXPECT_TRUE(bvh.closest_counted(Ray{{0, 0, -5}, {0, 0, 1}, 0.0f, kInf}, into).hit());
  EXPECT_GT(into.nodes, 1u);
  EXPECT_GT(into.triangles, 0u);
  const BruteForce brute(mesh, TraceConfig{});
  TraversalCost all;
  brute.closest_counted(Ray{{10, 10, 10}, {1, 0, 0}, 0.0f, kInf}, all);
  EXPECT_EQ(all.triangles, mesh.size());
  EXPECT_EQ(all.nodes, 0u);
}

}  // namespace
}  // namespace rayvec
