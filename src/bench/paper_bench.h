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

struct Table1Result {
  PaperModel model;
  uint32_t side = 0;      // image side used: rays = side²
  bool baselines = true;  // false when original/optimized were skipped
  Timing original, optimized, vec_paper, vec_mt;
  uint64_t mismatches = 0;      // rays where original, optimized and vectorized `paper` disagree
  uint64_t mt_differences = 0;  // rays where `mt` picks another triangle than `paper` (allowed)
  uint64_t rays() const { return uint64_t(side) * side; }
  double tests() const { return double(rays()) * model.triangles; }
};

struct ScalingResult {
  uint32_t side = 0, triangles = 0, threads = 0;
  Intersector intersector = Intersector::mt;
  Timing time;
  uint64_t mismatches = 0;  // rays whose hit differs from the one-thread run
};

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

// Timed runs of each thread count in the scaling run at least (unless min_seconds is 0): the 50,000
// triangle size takes ~3.5 s a run on one thread, so it used to be a single sample.
inline constexpr int kScalingMinRuns = 3;

// The vectorized brute force at 1..max_threads threads for one scaling size and intersector, the
// thread counts timed in turns (one run each per round), medians on the wall clock.
std::vector<ScalingResult> run_scaling(uint32_t side, uint32_t triangles, Isa isa, Intersector intersector,
                                       int max_threads, double min_seconds, const Progress& progress);

}  // namespace rayvec
