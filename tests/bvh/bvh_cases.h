// The parameter space of the BVH tests: every ISA × intersector × node width the ISA supports, with
// a readable gtest name (`avx512_mt_w8`). ISAs the CPU lacks stay in the list, so each test's SetUp
// can report them as skipped by name instead of passing silently.
#pragma once
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accel/accelerator.h"
#include "accel/bvh_accelerator.h"
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

// Fixture of the packet tests: skips the scalar ISA (no packets) by name; bvh(mesh) builds the
// case's BVH at its node width.
class BvhPacketCaseTest : public BvhCaseTest {
 protected:
  void SetUp() override {
    BvhCaseTest::SetUp();
    if (IsSkipped()) return;
    if (GetParam().isa == Isa::scalar) GTEST_SKIP() << "scalar has no packets: skipped";
  }
  BvhAccelerator bvh(const TriangleMesh& mesh) const {
    BvhOptions options;
    options.width = GetParam().width;
    return BvhAccelerator(mesh, config(), options);
  }
  // bvh(mesh), or null for a mesh the BVH refuses (a hard-case family with non-finite vertices).
  std::unique_ptr<BvhAccelerator> bvh_unless_refused(const TriangleMesh& mesh) const {
    try {
      return std::make_unique<BvhAccelerator>(bvh(mesh));
    } catch (const std::exception&) {
      return nullptr;
    }
  }
};

inline std::string bvh_case_name(const ::testing::TestParamInfo<BvhCase>& info) {
  return std::string(isa_name(info.param.isa)) + "_" + intersector_name(info.param.intersector) + "_w" +
         std::to_string(info.param.width);
}

}  // namespace rayvec::test
