// `bench paper` split into shares of rays, as its ranks run it under mpirun: shares of a row make
// the one-process row (hits, checksum, checks), and rank 0's second look at gathered hits finds a
// gather that is off by one ray.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "bench/paper_bench.h"
#include "bench/paper_shares.h"

namespace rayvec {
namespace {

const PaperModel& model(const char* name) {
  for (const PaperModel& m : kPaperTable1)
    if (std::strcmp(m.name, name) == 0) return m;
  throw std::logic_error(name);
}

bool same_bits(const std::vector<Hit>& a, const std::vector<Hit>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Hit)) == 0;
}

TEST(PaperShares, SharesMakeTheOneProcessRow) {
  const PaperModel& mod3 = model("mod3");
  const uint32_t side = 21;  // 441 rays: shares of 147, or of 221 and 220
  std::vector<Hit> whole;
  const Table1Share all = run_table1_share(mod3, side, 0, side * side, Isa::scalar, true, 0.0, {}, whole);
  const Table1Result one = run_table1_row(mod3, side, Isa::scalar, true, 0.0, {});
  EXPECT_EQ(one.checksum, hits_checksum(whole));
  EXPECT_GT(one.hits, 300u);
  EXPECT_EQ(one.shares.size(), 1u);
  for (int ranks : {2, 3}) {
    std::vector<Table1Share> shares;
    std::vector<Hit> gathered, part;
    for (int r = 0; r < ranks; ++r) {
      const uint64_t first = uint64_t(side * side) * r / ranks,
                     last = uint64_t(side * side) * (r + 1) / ranks;
      shares.push_back(run_table1_share(mod3, side, first, last, Isa::scalar, true, 0.0, {}, part));
      EXPECT_EQ(part.size(), last - first);
      EXPECT_EQ(hits_checksum(part, first),
                hits_checksum(std::span(whole).subspan(first, last - first), first));
      gathered.insert(gathered.end(), part.begin(), part.end());
    }
    EXPECT_TRUE(same_bits(gathered, whole)) << ranks;
    const Table1Result row = combine_table1_shares(mod3, side, true, shares, gathered);
    EXPECT_EQ(row.checksum, one.checksum);
    EXPECT_EQ(row.hits, one.hits);
    EXPECT_EQ(row.mismatches, 0u);
    EXPECT_EQ(row.mt_differences, all.mt_differences);
    EXPECT_EQ(row.shares.size(), std::size_t(ranks));
    EXPECT_EQ(retrace_differences(mod3, side, Isa::scalar, check_sample(row.shares), gathered), 0u);
  }
}

TEST(PaperShares, ChecksumOfSharesSumsToTheWhole) {
  std::vector<Hit> hits(10);
  for (int i = 0; i < 10; i += 3) hits[i] = Hit{0.5f + i, 0.1f, 0.2f, 7 * i};
  const uint64_t whole = hits_checksum(hits);
  EXPECT_EQ(hits_checksum(std::span(hits).first(4)) + hits_checksum(std::span(hits).subspan(4), 4), whole);
  // Order matters: the same hits in another order are another result.
  std::swap(hits[0], hits[3]);
  EXPECT_NE(hits_checksum(hits), whole);
}

TEST(PaperShares, RowTakesTheSlowestRankAndSumsTheChecks) {
  Table1Share a, b;
  a.first = 0, a.last = 3, b.first = 3, b.last = 5;
  a.vec_mt = Timing{1.0, 5, 3.0, 2.0};
  b.vec_mt = Timing{3.0, 7, 4.0, 1.0};
  a.mismatches = 1, b.mismatches = 2, a.mt_differences = 4, b.mt_differences = 8;
  const Table1Result r = combine_table1_shares(model("mod1"), 2, false, {a, b}, std::vector<Hit>(5));
  EXPECT_EQ(r.vec_mt.seconds, 3.0);
  EXPECT_EQ(r.vec_mt.repeats, 5);
  EXPECT_EQ(r.vec_mt.ghz, 3.5);
  EXPECT_EQ(r.vec_mt.fma_per_cycle, 1.5);
  EXPECT_EQ(r.mismatches, 3u);
  EXPECT_EQ(r.mt_differences, 12u);
  EXPECT_EQ(r.hits, 0u);
  EXPECT_EQ(share_imbalance(r.shares, &Table1Share::vec_mt), 1.5);  // 3 / mean(1, 3)
  EXPECT_EQ(share_imbalance(r.shares, &Table1Share::original), 0.0);
  EXPECT_EQ(r.tests_per_rank(), r.tests() / 2);
}

TEST(PaperShares, CheckSampleHoldsEveryShareEndAndEveryNthRay) {
  std::vector<Table1Share> shares(3);
  const uint64_t bounds[] = {0, 4, 7, 10};
  for (int r = 0; r < 3; ++r) shares[r].first = bounds[r], shares[r].last = bounds[r + 1];
  EXPECT_EQ(check_sample(shares), (std::vector<uint64_t>{0, 3, 4, 6, 7, 9}));
  EXPECT_TRUE(check_sample({}).empty());
}

TEST(PaperShares, RetraceFindsAGatherOffByOneRay) {
  const PaperModel& mod1 = model("mod1");
  const uint32_t side = 8;
  std::vector<Hit> hits;
  run_table1_share(mod1, side, 0, side * side, Isa::scalar, false, 0.0, {}, hits);
  std::vector<Table1Share> shares(2);
  shares[0].last = shares[1].first = 32;
  shares[1].last = 64;
  const std::vector<uint64_t> sample = check_sample(shares);
  EXPECT_EQ(retrace_differences(mod1, side, Isa::scalar, sample, hits), 0u);
  std::vector<Hit> shifted = hits;  // rank 1's share placed one ray early
  std::rotate(shifted.begin() + 32, shifted.begin() + 33, shifted.end());
  EXPECT_GT(retrace_differences(mod1, side, Isa::scalar, sample, shifted), 0u);
}

}  // namespace
}  // namespace rayvec
