// measure_fma_per_ns: the vector-throughput probe `bench paper` prints as FMA/c. Plausibility only
// (speed is never asserted in tests): per cycle of the measured clock, a core issues at least
// 0.05 and at most 8 FMAs of its widest vector (no x86-64 core has more than 4 FMA pipes; the
// upper bound catches a folded loop, the lower one a wrong count). ISAs the CPU lacks are skipped
// by name, and the probe reports 0 for them.
#include <gtest/gtest.h>

#include "bench/cpu_clock.h"
#include "bench/fma_rate.h"

namespace rayvec {
namespace {

class FmaRate : public ::testing::TestWithParam<Isa> {};

TEST_P(FmaRate, IsAPlausibleCountPerCycle) {
  const Isa isa = GetParam();
  if (!isa_supported(isa)) {
    EXPECT_EQ(measure_fma_per_ns(isa), 0.0);
    GTEST_SKIP() << isa_name(isa) << " not supported by this CPU";
  }
  const double ghz = measure_clock_ghz();
  const double per_cycle = measure_fma_per_ns(isa) / ghz;
  EXPECT_GT(per_cycle, 0.05) << isa_name(isa);
  EXPECT_LT(per_cycle, 8.0) << isa_name(isa);
}

INSTANTIATE_TEST_SUITE_P(EveryIsa, FmaRate, ::testing::Values(Isa::scalar, Isa::avx2, Isa::avx512),
                         [](const auto& info) { return std::string(isa_name(info.param)); });

}  // namespace
}  // namespace rayvec
