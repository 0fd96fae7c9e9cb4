// The measurements behind `rayvec accuracy` and docs/accuracy.md: for every intersector × ISA the
// throughput (brute-force triangle tests per second, BVH primary rays per second) and, per
// hard-case family, the false-miss, false-hit and wrong-nearest rates against the exact oracle.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "accuracy/scoring.h"

namespace rayvec {

struct AccuracySettings {
  int scale = 2;       // hard-case ray counts ×scale (hard_case_families)
  int bvh_size = 512;  // primary rays: bvh_size² pixels
  int repeats = 3;     // timings: median of this many runs (after a warm-up)
  uint64_t seed = 2026;
};

struct ModeResult {
  Intersector intersector;
  Isa isa;
  double brute_gtests = 0;  // brute force, 10^9 ray–triangle tests per second
  double bvh_mrays = 0;     // BVH primary rays, 10^6 rays per second (0: BVH unavailable)
  // Seconds of each timed repeat; repeat k of every intersector on one ISA ran back to back, so
  // ratios of the same repeat share the machine's load (paired ratios).
  std::vector<double> brute_seconds, bvh_seconds;
  std::vector<double> bvh_nonfinite_seconds;  // the same primary rays with a NaN/Inf field each
  std::vector<FamilyScore> families;          // same order as AccuracyReport::families
};

struct AccuracyReport {
  AccuracySettings settings;
  int threads = 0;
  std::string cpu;
  std::size_t brute_triangles = 0, brute_rays = 0, bvh_triangles = 0;
  std::vector<std::string> families;  // names
  std::vector<std::string> family_descriptions;
  std::vector<bool> family_crossing;
  std::vector<ModeResult> modes;  // every intersector × supported ISA
};

// Runs everything (tens of seconds at the default settings). Progress goes to `log` (may be null).
AccuracyReport measure_accuracy(const AccuracySettings& settings, std::FILE* log);

void write_accuracy_markdown(const AccuracyReport& report, std::FILE* out);
void write_accuracy_json(const AccuracyReport& report, std::FILE* out);

}  // namespace rayvec
