// The paper's scalar versions (Table 1's original AoS and optimized SoA kernels) against the scalar
// `paper` kernel: the same arithmetic, so the same bits.
#include <gtest/gtest.h>

#include <vector>

#include "bench/paper_baselines.h"
#include "kernels/kernel_scenes.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

TEST(PaperBaselines, OriginalAndOptimizedMatchPaperKernelExactly) {
  for (const test::KernelScene& s : {test::random_scene(), test::sphere_scene(), test::grid_scene()}) {
    const TriangleSoA soa(s.mesh);
    const std::vector<Hit> ref =
        test::closest_one_by_one(triangle_kernels(Isa::scalar, Intersector::paper), soa, s.rays);
    RayBatch batch;
    for (const Ray& r : s.rays) batch.push_back(r);
    std::vector<Hit> original(s.rays.size()), optimized(s.rays.size());
    closest_original(paper_aos_triangles(s.mesh), s.rays, 0, s.rays.size(), original);
    closest_optimized(paper_soa_triangles(s.mesh), batch, 0, s.rays.size(), optimized);
    for (std::size_t i = 0; i < s.rays.size(); ++i) {
      for (const Hit* h : {&original[i], &optimized[i]}) {
        ASSERT_EQ(h->tri, ref[i].tri) << s.name << " ray " << i;
        if (h->hit()) {
          ASSERT_EQ(h->t, ref[i].t) << s.name << " ray " << i;
          ASSERT_EQ(h->u, ref[i].u) << s.name << " ray " << i;
          ASSERT_EQ(h->v, ref[i].v) << s.name << " ray " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace rayvec
