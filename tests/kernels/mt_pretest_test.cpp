// The float `mt` kernels' two pre-test forms (MtPretest: sign bits, ordered compares) and the rule
// that picks one per CPU.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "kernels/closest_batch.h"
#include "kernels/kernel_scenes.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

using test::closest_one_by_one;
using test::KernelScene;

// The float `mt` kernels' two pre-tests (MtPretest) are conservative forms of the same conditions,
// so on every ISA they give the same hits bit for bit, one ray at a time and in batches (pairs).
TEST(MtPretest, BothFormsGiveTheSameHitsOnEveryIsa) {
  for (Isa isa : kAllIsas) {
    if (!isa_supported(isa)) {
      std::printf("[ skipped ] %s: this CPU lacks it\n", isa_name(isa));
      continue;
    }
    const TriangleKernels& sign = triangle_kernels(isa, Intersector::mt, MtPretest::sign_bits);
    const TriangleKernels& ordered = triangle_kernels(isa, Intersector::mt, MtPretest::ordered_compares);
    ASSERT_NE(sign.closest, ordered.closest) << isa_name(isa);
    for (const KernelScene& s :
         {test::random_scene(), test::sphere_scene(), test::grid_scene(), test::hard_scene()}) {
      const TriangleSoA soa(s.mesh);
      const std::vector<Hit> one = closest_one_by_one(sign, soa, s.rays),
                             got = closest_one_by_one(ordered, soa, s.rays);
      std::vector<Hit> batch(s.rays.size());
      closest_batch(ordered, soa.arrays(), 0, soa.size(), s.rays.data(), batch.data(), batch.size());
      int hits = 0;
      for (std::size_t i = 0; i < s.rays.size(); ++i) {
        hits += one[i].hit();
        for (const Hit* h : {&got[i], static_cast<const Hit*>(&batch[i])}) {
          ASSERT_EQ(h->tri, one[i].tri) << isa_name(isa) << " " << s.name << " ray " << i;
          if (h->hit()) {
            ASSERT_EQ(h->t, one[i].t) << isa_name(isa) << " " << s.name << " ray " << i;
            ASSERT_EQ(h->u, one[i].u) << isa_name(isa) << " " << s.name << " ray " << i;
            ASSERT_EQ(h->v, one[i].v) << isa_name(isa) << " " << s.name << " ray " << i;
          }
        }
      }
      EXPECT_GT(hits * 20, int(s.rays.size())) << s.name;
    }
  }
}

TEST(MtPretest, OrderedComparesOnlyForIntelAvx512) {
  EXPECT_EQ(default_mt_pretest(Isa::avx512, "GenuineIntel"), MtPretest::ordered_compares);
  EXPECT_EQ(default_mt_pretest(Isa::avx512, "AuthenticAMD"), MtPretest::sign_bits);
  EXPECT_EQ(default_mt_pretest(Isa::avx2, "GenuineIntel"), MtPretest::sign_bits);
  EXPECT_EQ(default_mt_pretest(Isa::scalar, "GenuineIntel"), MtPretest::sign_bits);
  for (Isa isa : supported_isas())  // the two-argument table is the running CPU's default
    EXPECT_EQ(&triangle_kernels(isa, Intersector::mt),
              &triangle_kernels(isa, Intersector::mt, default_mt_pretest(isa, cpu_features().vendor)));
}

}  // namespace
}  // namespace rayvec
