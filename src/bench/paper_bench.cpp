#include "bench/paper_bench.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "accel/accelerator.h"
#include "bench/cpu_clock.h"
#include "bench/fma_rate.h"
#include "bench/median.h"
#include "bench/paper_scene.h"
#include "bench/paper_baselines.h"
#include "bench/paper_shares.h"

namespace rayvec {

const PaperModel kPaperTable1[17] = {
    {"mod1", 40000, 2000, 1.016, 0.589, 0.061, 16.65, 9.65},
    {"mod2", 40000, 50000, 26.430, 16.523, 2.502, 10.56, 6.60},
    {"mod3", 1638400, 2000, 37.779, 20.037, 1.953, 19.34, 10.26},
    {"mod4", 10000, 2000, 0.274, 0.167, 0.027, 10.15, 6.18},
    {"mod5", 262144, 2000, 6.336, 3.473, 0.375, 16.89, 9.26},
    {"mod6", 1048576, 2000, 24.982, 13.137, 1.517, 16.47, 8.66},
    {"mod7", 4194304, 2000, 99.648, 49.072, 5.681, 17.54, 8.64},
    {"mod8", 40000, 5000, 1.496, 1.262, 0.138, 10.84, 9.14},
    {"mod9", 40000, 32258, 11.947, 6.926, 1.044, 11.44, 6.63},
    {"mod10", 40000, 15774, 5.861, 3.725, 0.391, 14.99, 9.53},
    {"mod11", 40000, 5000, 1.111, 0.824, 0.108, 10.29, 7.63},
    {"mod12", 40000, 5000, 1.503, 1.281, 0.146, 10.29, 8.77},
    {"mod13", 262144, 5000, 10.489, 8.377, 0.942, 11.13, 8.89},
    {"mod14", 262144, 32258, 82.729, 47.715, 6.621, 12.49, 7.21},
    {"mod15", 262144, 15744, 42.354, 23.581, 2.541, 16.67, 9.28},
    {"mod16", 262144, 5000, 7.828, 5.399, 0.702, 11.15, 7.69},
    {"mod17", 262144, 5000, 10.277, 7.794, 0.963, 10.67, 8.09},
};

namespace {

constexpr std::size_t kChunk = 64;  // rays per closest_stream call (and per OpenMP work item)

// Seconds on the wall clock, or on this thread's CPU-time clock: one-thread runs are timed by the
// latter, which does not count time the thread spends descheduled while other processes share the
// machine (on an idle machine the two agree).
double now(bool thread_cpu) {
  if (!thread_cpu)
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  return thread_cpu_seconds();
}

// Runs `fn` at least `min_runs` times and until `min_seconds` have passed in total (at most 15 runs,
// or min_runs if larger); the median. With `calibrate`, the core clock is measured before each of the
// first kVectorizedMinRuns runs (--quick repeats short runs up to 15 times; the clock needs fewer).
// `calibrate` also runs the FMA throughput probe of `isa` (bench/fma_rate.h) next to the clock.
template <typename Fn>
Timing time_median(double min_seconds, bool thread_cpu, Fn&& fn, int min_runs = 1, bool calibrate = false,
                   Isa isa = Isa::scalar) {
  std::vector<double> runs, clocks, fmas;
  double total = 0;
  do {
    if (calibrate && int(clocks.size()) < kVectorizedMinRuns) {
      clocks.push_back(measure_clock_ghz());
      const double per_ns = measure_fma_per_ns(isa);
      if (clocks.back() > 0) fmas.push_back(per_ns / clocks.back());
    }
    const double start = now(thread_cpu);
    fn();
    const double s = now(thread_cpu) - start;
    runs.push_back(s);
    total += s;
  } while (int(runs.size()) < min_runs || (total < min_seconds && runs.size() < 15));
  return Timing{median(runs), int(runs.size()), median(clocks), median(fmas)};
}

std::vector<Ray> to_rays(const RayBatch& batch) {
  std::vector<Ray> rays(batch.size());
  for (std::size_t i = 0; i < batch.size(); ++i) rays[i] = batch[i];
  return rays;
}

// The vectorized brute force as the library runs it: chunks of rays through closest_stream,
// OpenMP-dynamic over chunks when threads > 1.
void trace_vectorized(const Accelerator& accel, const std::vector<Ray>& rays, std::vector<Hit>& hits,
                      int threads) {
  const auto chunks = static_cast<std::int64_t>((rays.size() + kChunk - 1) / kChunk);
  auto run_chunk = [&](std::int64_t c) {
    const std::size_t begin = std::size_t(c) * kChunk;
    accel.closest_stream(rays.data() + begin, hits.data() + begin, std::min(kChunk, rays.size() - begin));
  };
  if (threads <= 1) {
    for (std::int64_t c = 0; c < chunks; ++c) run_chunk(c);
    return;
  }
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (std::int64_t c = 0; c < chunks; ++c) run_chunk(c);
}

// Rays [first, last) of `all`.
RayBatch ray_range(const RayBatch& all, uint64_t first, uint64_t last) {
  if (first == 0 && last >= all.size()) return all;
  RayBatch out;
  out.reserve(std::size_t(last - first));
  for (uint64_t i = first; i < last && i < all.size(); ++i) out.push_back(all[std::size_t(i)]);
  return out;
}

}  // namespace

uint32_t scaled_side(uint32_t rays, uint32_t divisor) {
  const double side = std::sqrt(double(rays)) / std::max(divisor, 1u);
  return std::max(1u, static_cast<uint32_t>(std::lround(side)));
}

Table1Result run_table1_row(const PaperModel& model, uint32_t side, Isa isa, bool baselines,
                            double min_seconds, const Progress& progress) {
  std::vector<Hit> hits;
  const uint64_t n = uint64_t(side) * side;
  Table1Share share = run_table1_share(model, side, 0, n, isa, baselines, min_seconds, progress, hits);
  return combine_table1_shares(model, side, baselines, {share}, hits);
}

Table1Share run_table1_share(const PaperModel& model, uint32_t side, uint64_t first, uint64_t last, Isa isa,
                             bool baselines, double min_seconds, const Progress& progress,
                             std::vector<Hit>& paper_hits) {
  Table1Share out;
  out.first = first;
  out.last = last;
  const TriangleMesh mesh = paper_triangles(model.triangles);
  const RayBatch batch = ray_range(paper_camera_rays(side), first, last);
  const std::vector<Ray> rays = to_rays(batch);
  const std::size_t n = rays.size();
  auto say = [&](const char* what) {
    if (progress) progress(std::string(model.name) + ": " + what);
  };

  std::vector<Hit>& vec_paper = paper_hits;
  std::vector<Hit> vec_mt(n);
  vec_paper.assign(n, Hit{});
  const int runs = min_seconds > 0 ? kVectorizedMinRuns : 1;
  {
    say("vectorized (paper)");
    const auto accel = make_accelerator(AccelKind::brute, mesh, {isa, Intersector::paper});
    out.vec_paper = time_median(
        min_seconds, true, [&] { trace_vectorized(*accel, rays, vec_paper, 1); }, runs, true, isa);
  }
  {
    say("vectorized (mt)");
    const auto accel = make_accelerator(AccelKind::brute, mesh, {isa, Intersector::mt});
    out.vec_mt = time_median(
        min_seconds, true, [&] { trace_vectorized(*accel, rays, vec_mt, 1); }, runs, true, isa);
  }
  for (std::size_t i = 0; i < n; ++i) out.mt_differences += vec_mt[i].tri != vec_paper[i].tri;
  if (!baselines) return out;

  std::vector<Hit> original(n), optimized(n);
  {
    say("original");
    const PaperAosTriangles aos = paper_aos_triangles(mesh);
    out.original = time_median(min_seconds, true, [&] { closest_original(aos, rays, 0, n, original); });
  }
  {
    say("optimized");
    const PaperSoaTriangles soa = paper_soa_triangles(mesh);
    out.optimized = time_median(min_seconds, true, [&] { closest_optimized(soa, batch, 0, n, optimized); });
  }
  for (std::size_t i = 0; i < n; ++i)
    out.mismatches += !same_hit(original[i], vec_paper[i]) || !same_hit(optimized[i], vec_paper[i]);
  return out;
}

std::vector<ScalingResult> run_scaling(uint32_t side, uint32_t triangles, Isa isa, Intersector intersector,
                                       int max_threads, double min_seconds, const Progress& progress,
                                       uint64_t first, uint64_t last, const AllMax& all_max) {
  const TriangleMesh mesh = paper_triangles(triangles);
  last = std::min(last, uint64_t(side) * side);
  const std::vector<Ray> rays = to_rays(ray_range(paper_camera_rays(side), first, last));
  const auto accel = make_accelerator(AccelKind::brute, mesh, {isa, intersector});
  std::vector<Hit> reference(rays.size()), hits(rays.size());
  // The thread counts take turns, one run each per round, until each has run for min_seconds and
  // kScalingMinRuns rounds (at most 15 rounds): on a VM whose speed drifts for seconds at a time, timing all
  // one-thread runs and then all two-thread runs would put the drift into the speedup.
  std::vector<ScalingResult> out(std::size_t(std::max(max_threads, 1)));
  std::vector<std::vector<double>> runs(out.size());
  std::vector<double> total(out.size(), 0.0);
  const int min_runs = min_seconds > 0 ? kScalingMinRuns : 1;
  for (int round = 0; round < 15; ++round) {
    // Which thread counts run again; across ranks, those that any rank still needs, so that every
    // rank makes the same runs.
    std::vector<int64_t> again(out.size());
    for (std::size_t k = 0; k < out.size(); ++k)
      again[k] = round == 0 || total[k] < min_seconds || int(runs[k].size()) < min_runs;
    if (all_max) all_max(again);
    if (std::find(again.begin(), again.end(), 1) == again.end()) break;
    for (int threads = 1; threads <= int(out.size()); ++threads) {
      const std::size_t k = std::size_t(threads - 1);
      if (!again[k]) continue;
      if (progress && round == 0)
        progress(std::to_string(triangles) + " triangles, " + intersector_name(intersector) + ", " +
                 std::to_string(threads) + " thread(s)");
      std::vector<Hit>& dst = threads == 1 ? reference : hits;
      if (all_max) {
        std::vector<int64_t> start_together(1);  // a collective: no rank starts before all are here
        all_max(start_together);
      }
      const double start = now(false);
      trace_vectorized(*accel, rays, dst, threads);
      runs[k].push_back(now(false) - start);
      total[k] += runs[k].back();
      if (threads > 1 && round == 0)
        for (std::size_t i = 0; i < rays.size(); ++i) out[k].mismatches += !same_hit(hits[i], reference[i]);
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    ScalingResult& r = out[k];
    r.side = side;
    r.triangles = triangles;
    r.threads = uint32_t(k + 1);
    r.intersector = intersector;
    r.first = first;
    r.last = last;
    r.share_seconds = median(runs[k]);
    std::vector<double> slowest = runs[k];
    if (all_max) {
      std::vector<int64_t> ns(runs[k].size());
      for (std::size_t i = 0; i < ns.size(); ++i) ns[i] = int64_t(runs[k][i] * 1e9);
      all_max(ns);
      for (std::size_t i = 0; i < ns.size(); ++i) slowest[i] = double(ns[i]) * 1e-9;
    }
    r.time = Timing{median(slowest), int(runs[k].size()), 0.0};
  }
  return out;
}

}  // namespace rayvec
