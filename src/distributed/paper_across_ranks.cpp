#include "distributed/paper_across_ranks.h"

#include <chrono>
#include <type_traits>

#include "bench/paper_shares.h"
#include "distributed/rays_across_ranks.h"
#include "io/input_error.h"
#include "platform/stopwatch.h"

namespace rayvec {

Table1Result table1_row_across_ranks(Cluster& cluster, const PaperModel& model, uint32_t side, Isa isa,
                                     bool baselines, double min_seconds, const Progress& progress) {
  if (!cluster.distributed()) return run_table1_row(model, side, isa, baselines, min_seconds, progress);
  static_assert(std::is_trivially_copyable_v<Table1Share> && std::is_trivially_copyable_v<Hit>);
  cluster.begin_collective();
  const auto [first, last] = share_of(uint64_t(side) * side, cluster.rank(), cluster.size());
  std::vector<Hit> hits;
  const Table1Share mine =
      run_table1_share(model, side, first, last, isa, baselines, min_seconds, progress, hits);
  cluster.test_failure_point();
  // Every rank is done before rank 0 starts the gather's clock, so that it times the transfer, not
  // the wait for the slowest rank.
  std::vector<int64_t> all_done(1);
  cluster.all_max(all_done);
  if (!cluster.root()) {
    cluster.send_vector(0, kTagResults, std::vector<Table1Share>{mine});
    cluster.send_vector(0, kTagResults, hits);
    Table1Result own = combine_table1_shares(model, side, baselines, {mine}, {});
    return own;
  }
  // Rank 0: the shares in rank order, hence the hits in input order.
  const auto t = std::chrono::steady_clock::now();
  std::vector<Table1Share> shares{mine};
  for (int r = 1; r < cluster.size(); ++r) {
    const std::vector<Table1Share> share = cluster.recv_vector<Table1Share>(r, kTagResults);
    const std::vector<Hit> part = cluster.recv_vector<Hit>(r, kTagResults);
    if (share.size() != 1 || share[0].first != hits.size() || part.size() != share[0].rays())
      throw RuntimeError("bench paper: rank " + std::to_string(r) +
                         " sent a share that does not follow rank " + std::to_string(r - 1) + "'s");
    shares.push_back(share[0]);
    hits.insert(hits.end(), part.begin(), part.end());
  }
  const double gather = seconds_since(t);
  Table1Result row = combine_table1_shares(model, side, baselines, std::move(shares), hits);
  row.gather_seconds = gather;
  if (progress) progress(std::string(model.name) + ": checking the gathered hits");
  const std::vector<uint64_t> sample = check_sample(row.shares);
  row.checked_rays = sample.size();
  row.rank_differences = retrace_differences(model, side, isa, sample, hits);
  row.mismatches += row.rank_differences;
  return row;
}

std::vector<ScalingResult> scaling_across_ranks(Cluster& cluster, uint32_t side, uint32_t triangles, Isa isa,
                                                Intersector intersector, int max_threads, double min_seconds,
                                                const Progress& progress) {
  if (!cluster.distributed())
    return run_scaling(side, triangles, isa, intersector, max_threads, min_seconds, progress);
  cluster.begin_collective();
  const auto [first, last] = share_of(uint64_t(side) * side, cluster.rank(), cluster.size());
  std::vector<ScalingResult> rows =
      run_scaling(side, triangles, isa, intersector, max_threads, min_seconds, progress, first, last,
                  [&](std::vector<int64_t>& v) { cluster.all_max(v); });
  // Per thread count: the mismatches summed; each rank's rays and median seconds, for rank 0.
  const std::size_t ranks = std::size_t(cluster.size()), me = std::size_t(cluster.rank());
  std::vector<int64_t> sums(rows.size() * (1 + 2 * ranks), 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    int64_t* row = &sums[k * (1 + 2 * ranks)];
    row[0] = int64_t(rows[k].mismatches);
    row[1 + 2 * me] = int64_t(rows[k].last - rows[k].first);
    row[2 + 2 * me] = int64_t(rows[k].share_seconds * 1e9);
  }
  cluster.all_sum(sums);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const int64_t* row = &sums[k * (1 + 2 * ranks)];
    rows[k].mismatches = uint64_t(row[0]);
    for (std::size_t r = 0; r < ranks; ++r) {
      rows[k].rank_rays.push_back(uint64_t(row[1 + 2 * r]));
      rows[k].rank_seconds.push_back(double(row[2 + 2 * r]) * 1e-9);
    }
  }
  return rows;
}

}  // namespace rayvec
