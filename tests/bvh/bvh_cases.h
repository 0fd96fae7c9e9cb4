// The parameter space of the BVH tests: every ISA × intersector × node width the ISA supports, with
// a readable gtest name (`avx512_mt_w8`). ISAs the CPU lacks stay in the list, so each test's SetUp
// can report them as skipped by name instead of passing silently.
#pragma once
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accel/accelerator.h"
#include "bvh/bvh_traversal.h"
#include "kernels/intersector.h"
#include "platform/isa.h"

namespace rayvec::test {

struct BvhCase {
  Isa isa;
  Intersector intersector;
  int width;
};

inline std::vector<BvhCase> bvh_cases(const std::vector<Intersector>& intersectors) {
  std::vector<BvhCase> cases;
  for (Isa isa : kAllIsas) {
    const BvhWidths w = bvh_widths(isa);
    for (Intersector i : intersectors)
      for (int k = 0; k < w.count; ++k) cases.push_back({isa, i, w.widths[k]});
  }
  return cases;
}

// Base fixture: skips (by name) the cases whose ISA the CPU lacks; config() is the case's tracer.
class BvhCaseTest : public ::testing::TestWithParam<BvhCase> {
 protected:
  void SetUp() override {
    if (!isa_supported(GetParam().isa))
      GTEST_SKIP() << "CPU lacks " << isa_name(GetParam().isa) << ": skipped";
  }
  TraceConfig config() const { return {GetParam().isa, GetParam().intersector}; }
};

inline std::string bvh_case_name(const ::testing::TestParamInfo<BvhCase>& info) {
  return std::string(isa_name(info.param.isa)) + "_" + intersector_name(info.param.intersector) + "_w" +
         std::to_string(info.param.width);
}

}  // namespace rayvec::test
