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

// --pretest chooses the mt kernels' pre-test for the run (a tuning switch for comparing the two on
// one CPU): it is named in the header and the JSON, and both give the same hits (counted here as the
// rays where mt's triangle differs from paper's).
TEST(BenchPaper, PretestSwitchIsReportedAndKeepsTheHits) {
  std::string differences[2];
  const char* names[2] = {"sign", "ordered"};
  for (int k = 0; k < 2; ++k) {
    const std::string args =
        std::string("bench paper --models mod2,mod7 --no-baselines --no-scaling --side-divisor 16 ") +
        "--pretest " + names[k];
    const auto text = test::run_cli(args);
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find(k == 0 ? "mt pre-test: sign bits, --pretest"
                                   : "mt pre-test: ordered compares, --pretest"),
              std::string::npos)
        << text.out;
    const auto json = test::run_cli(args + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    EXPECT_NE(json.out.find(k == 0 ? "\"mt_pretest\":\"sign bits\"" : "\"mt_pretest\":\"ordered compares\""),
              std::string::npos);
    for (std::size_t at = json.out.find("\"mt_differences\":"); at != std::string::npos;
         at = json.out.find("\"mt_differences\":", at + 1))
      differences[k] += json.out.substr(at, json.out.find_first_of(",}", at) - at) + ";";
  }
  EXPECT_EQ(test::count_of(differences[0], ";"), 2) << differences[0];
  EXPECT_EQ(differences[0], differences[1]);
  const auto bad = test::run_cli("bench paper --models mod2 --side-divisor 128 --pretest fastest");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--pretest: 'fastest' is not auto, sign or ordered"), std::string::npos) << bad.err;
}

TEST(BenchPaper, UnknownModelIsAUsageError) {
  const auto r = test::run_cli("bench paper --models mod99 --side-divisor 128");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("mod99"), std::string::npos);
}

}  // namespace
}  // namespace rayvec
