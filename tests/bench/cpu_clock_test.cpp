// measure_clock_ghz: the clock that `bench paper` turns G tests/s into tests per cycle with. Only a
// plausibility range — every x86-64 core of the last 20 years runs between 0.3 and 7 GHz (the fastest
// boost clock shipped is 6.2 GHz) — so a broken loop (folded away: huge, as the add-immediate chain
// that Intel's Golden Cove cores fold at rename read 13-14 GHz; wrong count or clock: tiny) fails,
// whatever the machine's load.
#include <gtest/gtest.h>

#include "bench/cpu_clock.h"

namespace rayvec {
namespace {

TEST(CpuClock, MeasuresAPlausibleGigahertz) {
  const double ghz = measure_clock_ghz();
  EXPECT_GT(ghz, 0.3);
  EXPECT_LT(ghz, 7.0);
}

TEST(CpuClock, ThreadCpuTimeAdvancesWithWork) {
  const double start = thread_cpu_seconds();
  measure_clock_ghz();
  EXPECT_GT(thread_cpu_seconds(), start);
}

}  // namespace
}  // namespace rayvec
