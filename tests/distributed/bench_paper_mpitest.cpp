// `mpirun -np 2 rayvec bench paper`: every row's rays split between the ranks, the hits gathered in
// input order are those of one process (same hits and checksum per row, no mismatch), rank 0
// prints for both with each rank's share; a bad option stops both ranks with one message.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "distributed/mpi_run.h"

namespace rayvec {
namespace {

// Every "hits":N,"checksum":"0x<16 hex digits>" of a JSON report, in row order.
std::vector<std::string> hits_and_checksums(const std::string& json) {
  std::vector<std::string> out;
  const std::string hits = "\"hits\":", checksum = ",\"checksum\":\"0x";
  for (std::size_t at = json.find(hits); at != std::string::npos; at = json.find(hits, at + 1)) {
    const std::size_t digits = json.find_first_not_of("0123456789", at + hits.size());
    if (digits == at + hits.size() || json.compare(digits, checksum.size(), checksum) != 0) continue;
    const std::size_t hex = digits + checksum.size();
    if (json.find_first_not_of("0123456789abcdef", hex) != hex + 16 || json.compare(hex + 16, 1, "\"") != 0)
      continue;
    out.push_back(json.substr(at, hex + 17 - at));
  }
  return out;
}

// All 17 rows and the scaling run at the smallest sizes (--side-divisor: one timed run each).
const std::string kTiny = "bench paper --side-divisor 128 --threads 2";

TEST(MpiBenchPaper, TwoRanksGatherTheHitsOfOneProcess) {
  const auto one = test::run_cli(kTiny + " --json");
  ASSERT_EQ(one.status, 0) << one.err;
  const auto two = test::run_mpi(kTiny + " --json");
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(hits_and_checksums(one.out).size(), 17u) << one.out;
  EXPECT_EQ(hits_and_checksums(two.out), hits_and_checksums(one.out));
  EXPECT_NE(two.out.find("\"ranks\":2,"), std::string::npos);
  EXPECT_EQ(test::count_of(two.out, "\"shares\":{\"first\":[0,"), 17) << two.out;
  EXPECT_EQ(test::count_of(two.out, "\"rank_differences\":0}"), 17) << two.out;
  EXPECT_EQ(test::count_of(two.out, "\"rank_seconds\":["), 12) << two.out;  // 3 sizes x 2 kernels x 2 threads
  EXPECT_NE(two.out.find("\"mismatches\":0}\n"), std::string::npos);
  EXPECT_EQ(test::count_of(two.out, "{\"cpu\":"), 1) << "rank 0 alone prints";
}

TEST(MpiBenchPaper, TextShowsEachRanksShare) {
  const auto two = test::run_mpi(kTiny + " --models mod3,mod7 --no-scaling");
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(test::count_of(two.out, "ranks: 2 ("), 1) << two.out;
  EXPECT_EQ(test::count_of(two.out, "Table 1 across 2 ranks"), 1) << two.out;
  // mod3: 1280 / 128 = 10, 100 rays; mod7: 2048 / 128 = 16, 256 rays.
  EXPECT_NE(two.out.find("\nmod3   rays 50, 50 | original "), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("\nmod7   rays 128, 128 | original "), std::string::npos) << two.out;
  EXPECT_EQ(test::count_of(two.out, ", 0 differ\n"), 2) << two.out;
  EXPECT_NE(two.out.find("): 0\n"), std::string::npos) << two.out;  // the mismatch total
}

TEST(MpiBenchPaper, BadOptionStopsEveryRankWithOneMessage) {
  const auto r = test::run_mpi("bench paper --models mod2,mod99 --side-divisor 128");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(test::count_of(r.err, "unknown model 'mod99'"), 1) << r.err;
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace rayvec
