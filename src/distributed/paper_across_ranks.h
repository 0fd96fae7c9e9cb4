// `bench paper` across the ranks of a cluster: every rank generates the same scene (it is
// deterministic, bench/paper_scene.h) and times its contiguous share of each row's rays on its own
// clock, as one process times all of them; rank 0 gathers the shares' timings and the hits in input
// order and checks the hits against its own. In a cluster of one these are the one-process runs.
#pragma once
#include <vector>

#include "bench/paper_bench.h"
#include "distributed/cluster.h"

namespace rayvec {

// A Table 1 row, every column (the scalar baselines too) split into shares of the rays. On rank 0
// the combined row (bench/paper_shares.h) with `checked_rays` of the gathered hits traced again on
// rank 0 and the differences counted into `mismatches`; on the other ranks their own share only.
Table1Result table1_row_across_ranks(Cluster& cluster, const PaperModel& model, uint32_t side, Isa isa,
                                     bool baselines, double min_seconds, const Progress& progress);

// A scaling size: every rank runs 1..max_threads threads on its share, the ranks starting each run
// together (ranks × threads workers in all); a run takes the slowest rank's wall time. Mismatches
// against one thread are summed over the ranks; rank 0 gets every rank's rays and median seconds.
std::vector<ScalingResult> scaling_across_ranks(Cluster& cluster, uint32_t side, uint32_t triangles, Isa isa,
                                                Intersector intersector, int max_threads, double min_seconds,
                                                const Progress& progress);

}  // namespace rayvec
