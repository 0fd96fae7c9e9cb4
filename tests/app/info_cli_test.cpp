// `rayvec info` names, for every ISA this CPU supports, the choices rayvec makes for it (the kernels'
// pre-test by CPU vendor, the BVH's node width and leaf size by mesh size), and where the BVH keeps
// the `mt` normals, so a benchmark row can be traced to the kernels and the tree that produced it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <string_view>

#include "accel/bvh_accelerator.h"
#include "bvh/bvh_traversal.h"
#include "kernels/triangle_kernels.h"
#include "platform/isa.h"
#include "test_support.h"

namespace rayvec {
namespace {

TEST(InfoCli, NamesTheMtPretestOfEverySupportedIsa) {
  const auto r = test::run_cli("info");
  ASSERT_EQ(r.status, 0) << r.err;
  for (Isa isa : kAllIsas) {
    const std::string head = std::string("  ") + isa_name(isa);
    const std::size_t at = r.out.find(head + " ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
    if (!isa_supported(isa)) {
      EXPECT_NE(line.find("not supported"), std::string::npos) << line;
      continue;
    }
    const std::string pretest = mt_pretest_name(default_mt_pretest(isa, cpu_features().vendor));
    EXPECT_NE(line.find("mt pre-test: " + pretest), std::string::npos) << line;
  }
}

TEST(InfoCli, NamesTheBvhShapeOfEverySupportedSimdIsa) {
  const auto r = test::run_cli("info");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string_view vendor = cpu_features().vendor;
  for (Isa isa : {Isa::avx2, Isa::avx512}) {
    if (!isa_supported(isa)) {
      std::printf("skipped ISA %s: not on this CPU\n", isa_name(isa));
      continue;
    }
    const std::size_t at = r.out.find(std::string("  ") + isa_name(isa) + " ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::size_t bvh = r.out.find('\n', at) + 1;  // the line after the ISA's
    const std::string line = r.out.substr(bvh, r.out.find('\n', bvh) - bvh);
    const std::string expected =
        "bvh: " + std::to_string(default_bvh_width(isa, kWideNodeTriangles - 1, vendor)) +
        "-wide nodes and " + std::to_string(default_leaf_steps(isa, kWideNodeTriangles - 1)) +
        "-step leaves below " + std::to_string(kWideNodeTriangles) +
        " triangles (costed per step or per half step, whichever tree costs less), " +
        std::to_string(default_bvh_width(isa, kWideNodeTriangles, vendor)) + "-wide and " +
        std::to_string(default_leaf_steps(isa, kWideNodeTriangles)) + "-step from there";
    EXPECT_NE(line.find(expected), std::string::npos) << line << "\nexpected: " << expected;
  }
}

TEST(InfoCli, NamesWhereTheBvhKeepsTheMtNormals) {
  const auto r = test::run_cli("info");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string expected = "bvh normals (mt): stored below " + std::to_string(kFormedNormalsFrom) +
                               " triangles while the tree fits " + std::to_string(int(kBvhBytesPerTriangle)) +
                               " bytes a triangle, else formed per step";
  EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
}

TEST(InfoCli, NamesHowTheBvhLeavesReachTheKernel) {
  const auto r = test::run_cli("info");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::size_t large = kWideNodeTriangles;
  const std::string expected =
      std::string("bvh leaf kernel (mt, watertight on avx2 and avx512): ") +
      leaf_call_name(default_leaf_call(Isa::avx512, Intersector::watertight, large - 1)) + " below " +
      std::to_string(large) + " triangles, " +
      leaf_call_name(default_leaf_call(Isa::avx512, Intersector::watertight, large)) + " from there";
  EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rayvec
