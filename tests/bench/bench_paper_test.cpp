// `rayvec bench paper` at a tiny size, so the reproduction command cannot rot. Checks the structure
// and the in-run verification, never the timings (speed is measured by the command, not by tests).
#include <gtest/gtest.h>

#include <string>

#include "test_support.h"

namespace rayvec {
namespace {

TEST(BenchPaper, TinyRunPrintsEveryModelAndNoMismatch) {
  const auto r = test::run_cli("bench paper --side-divisor 128 --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cpu: "), std::string::npos);
  EXPECT_NE(r.out.find("isa: "), std::string::npos);
  EXPECT_NE(r.out.find("threads: 2"), std::string::npos);
  for (int m = 1; m <= 17; ++m)
    EXPECT_NE(r.out.find("\nmod" + std::to_string(m) + " "), std::string::npos) << "mod" << m;
  EXPECT_NE(r.out.find("Thread scaling"), std::string::npos);
  EXPECT_NE(r.out.find("): 0\n"), std::string::npos) << r.out;  // the mismatch total
}

TEST(BenchPaper, JsonHasSeventeenRowsAndScaling) {
  const auto r = test::run_cli("bench paper --side-divisor 512 --threads 2 --json --isa scalar");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_FALSE(r.out.empty());
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_EQ(test::count_of(r.out, "\"model\":"), 17);
  EXPECT_EQ(test::count_of(r.out, "\"paper\":{"), 17);
  EXPECT_EQ(test::count_of(r.out, "\"tests_per_cycle\":{"), 17);  // with the clock measured in the run
  EXPECT_EQ(test::count_of(r.out, "\"clock_ghz\":{\"vectorized_paper\":0,"), 0);
  EXPECT_EQ(test::count_of(r.out, "\"fma_per_cycle\":{"), 17);  // the throughput probe, measured too
  EXPECT_EQ(test::count_of(r.out, "\"fma_per_cycle\":{\"vectorized_paper\":0,"), 0);
  // 3 sizes x 2 intersectors x threads 1..2
  EXPECT_EQ(test::count_of(r.out, "\"threads\":1,\"seconds\""), 6);
  EXPECT_EQ(test::count_of(r.out, "\"threads\":2,\"seconds\""), 6);
  EXPECT_NE(r.out.find("\"isa\":\"scalar\""), std::string::npos);
  EXPECT_NE(r.out.find("\"ranks\":1,"), std::string::npos);
  EXPECT_EQ(test::count_of(r.out, "\"checksum\":\"0x"),
            17);                                       // of the hits, to compare with a run across ranks
  EXPECT_EQ(test::count_of(r.out, "\"shares\":"), 0);  // per-rank data only across ranks
  EXPECT_NE(r.out.find("\"mismatches\":0}\n"), std::string::npos);
}

TEST(BenchPaper, UnknownModelIsAUsageError) {
  const auto r = test::run_cli("bench paper --models mod99 --side-divisor 128");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("mod99"), std::string::npos);
}

}  // namespace
}  // namespace rayvec
