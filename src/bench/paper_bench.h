// The measurements of `rayvec bench paper`: Sena et al. (2018) Table 1 (original, optimized and
// vectorized on one thread) and their section 5.2 thread-scaling run, on the generated scene of
// paper_scene.h. Printing lives in src/app/cmd_bench_paper.cpp; this file only measures and checks.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "io/progress.h"
#include "kernels/intersector.h"
#include "platform/isa.h"
#include "rays/ray.h"

namespace rayvec {

// One row of the paper's Table 1, with the paper's own numbers (seconds; Xeon Platinum 8160, icc).
struct PaperModel {
  const char* name;
  uint32_t rays, triangles;
  double original_s, optimized_s, vectorized_s;
  double speedup_original, speedup_optimized;  // original/vectorized, optimized/vectorized
};
extern const PaperModel kPaperTable1[17];

// Section 5.2: 16,777,216 rays (4096²) against 2,000 / 10,000 / 50,000 triangles.
inline constexpr uint32_t kPaperScalingSide = 4096;
inline constexpr uint32_t kPaperScalingTriangles[3] = {2000, 10000, 50000};

// A timing: the median of `repeats` runs (short runs are repeated so the clock's resolution and
// noise from other processes matter less). Table 1 (one thread) is timed on the thread's CPU-time
// clock, so other processes on a shared machine inflate it less; the scaling run on the wall clock,
// since only wall time shows what threads gain.
struct Timing {
  double seconds = 0;
  int repeats = 0;
  double ghz = 0;  // vectorized Table 1 runs: median core clock measured before each run (else 0)
  // Vectorized Table 1 runs: median vector FMAs per cycle of a throughput probe before each run
  // (bench/fma_rate.h; 2 on an uncontended two-FMA-pipe core), else 0.
  double fma_per_cycle = 0;
  // Tests per cycle of `tests` done in `seconds` at `ghz` (0 when the clock was not measured).
  double tests_per_cycle(double tests) const {
    return ghz > 0 && seconds > 0 ? tests / seconds / (ghz * 1e9) : 0;
  }
};

// One rank's part of a Table 1 row: the rays [first, last) of the row's side² rays (all of them in
// one process), timed and checked by that rank alone. Trivially copyable: a rank sends it to rank 0
// as bytes.
struct Table1Share {
  uint64_t first = 0, last = 0;
  Timing original, optimized, vec_paper, vec_mt;
  uint64_t mismatches = 0;      // rays of the share where original, optimized and vectorized `paper` disagree
  uint64_t mt_differences = 0;  // rays of the share where `mt` picks another triangle than `paper`
  uint64_t rays() const { return last - first; }
};

// A Table 1 row, whole: in one process its single share; across ranks the shares combined
// (bench/paper_shares.h: each column the slowest rank's seconds, the checks summed).
struct Table1Result {
  PaperModel model;
  uint32_t side = 0;      // image side used: rays = side²
  bool baselines = true;  // false when original/optimized were skipped
  Timing original, optimized, vec_paper, vec_mt;
  uint64_t mismatches = 0;          // rays where original, optimized and vectorized `paper` disagree
  uint64_t mt_differences = 0;      // rays where `mt` picks another triangle than `paper` (allowed)
  uint64_t hits = 0;                // rays that hit a triangle (vectorized `paper`)
  uint64_t checksum = 0;            // hits_checksum of vectorized `paper`'s hits, in input order
  std::vector<Table1Share> shares;  // by rank; one in one process
  // Across ranks: rays rank 0 traced again itself after the gather, and how many of them differ
  // from the gathered hit (counted in `mismatches`).
  uint64_t checked_rays = 0, rank_differences = 0;
  double gather_seconds = 0;  // rank 0: receiving the other ranks' shares and hits
  uint64_t rays() const { return uint64_t(side) * side; }
  double tests() const { return double(rays()) * model.triangles; }
  // Ray-triangle tests of the slowest rank's share when the shares are even: tests per cycle per core.
  double tests_per_rank() const { return tests() / double(shares.empty() ? 1 : shares.size()); }
};

struct ScalingResult {
  uint32_t side = 0, triangles = 0, threads = 0;
  Intersector intersector = Intersector::mt;
  Timing time;              // across ranks: per run the slowest rank's wall time, median over the runs
  uint64_t mismatches = 0;  // rays whose hit differs from the one-thread run
  // Across ranks: this rank's share of the rays and its own median; rank 0 collects every rank's in
  // rank_rays / rank_seconds (empty in one process).
  uint64_t first = 0, last = 0;
  double share_seconds = 0;
  std::vector<uint64_t> rank_rays;
  std::vector<double> rank_seconds;
};

// What a distributed scaling run borrows from its cluster to keep its ranks in step: an element-wise
// max over the ranks, in place (every rank makes the same calls in the same order). Empty in one
// process.
using AllMax = std::function<void(std::vector<int64_t>&)>;

// Image side for `rays` (a perfect square) divided by `divisor`, rounded to nearest, at least 1.
uint32_t scaled_side(uint32_t rays, uint32_t divisor);

// Timed runs of each vectorized Table 1 column at least (unless min_seconds is 0, i.e. testing): one
// run of mod2 takes ~0.5 s, over the 0.2 s minimum, so it would otherwise be a single sample — and on
// a shared virtual machine single samples of the same kernel differ widely
// (benchmarks.md#decision-bench-timing).
inline constexpr int kVectorizedMinRuns = 5;

// One Table 1 row on one thread: original and optimized (unless !baselines) and the vectorized
// brute force of `isa` with the `paper` and `mt` intersectors; checks that ids agree. The vectorized
// timings carry the core clock and the FMA throughput measured before each run (Timing::ghz,
// Timing::fma_per_cycle).
Table1Result run_table1_row(const PaperModel& model, uint32_t side, Isa isa, bool baselines,
                            double min_seconds, const Progress& progress);

// The same for the rays [first, last) of the row only (one rank's share): its timings and checks, and
// vectorized `paper`'s hits of those rays in `paper_hits` (last - first of them).
Table1Share run_table1_share(const PaperModel& model, uint32_t side, uint64_t first, uint64_t last, Isa isa,
                             bool baselines, double min_seconds, const Progress& progress,
                             std::vector<Hit>& paper_hits);

// Timed runs of each thread count in the scaling run at least (unless min_seconds is 0): the 50,000
// triangle size takes ~3.5 s a run on one thread, so it used to be a single sample.
inline constexpr int kScalingMinRuns = 3;

// The vectorized brute force at 1..max_threads threads for one scaling size and intersector, the
// thread counts timed in turns (one run each per round), medians on the wall clock. With `all_max`
// (across ranks) each rank traces only the rays [first, last), the ranks agree each round on which
// thread counts run again and start each run together, and a run's time is the slowest rank's.
std::vector<ScalingResult> run_scaling(uint32_t side, uint32_t triangles, Isa isa, Intersector intersector,
                                       int max_threads, double min_seconds, const Progress& progress,
                                       uint64_t first = 0, uint64_t last = UINT64_MAX,
                                       const AllMax& all_max = {});

}  // namespace rayvec
