// `rayvec bench paper`: reproduces Sena et al. (2018) — Table 1 (original, optimized and vectorized
// on one thread, 17 sizes) and the section 5.2 thread-scaling run — on the generated scene of
// src/bench/paper_scene.h, printing a text table or one JSON object. Measurement: src/bench/paper_bench.cpp.
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/bench_paper_report.h"
#include "app/trace_options.h"
#include "bench/paper_bench.h"
#include "bench/paper_scene.h"
#include "bench/paper_shares.h"
#include "distributed/paper_across_ranks.h"
#include "io/input_error.h"
#include "io/json_string.h"
#include "io/progress.h"
#include "kernels/triangle_kernels.h"

namespace rayvec {
namespace {

// Ray scale-downs (the image side is divided, so ray counts stay perfect squares):
constexpr uint32_t kQuickTableDivisor = 8;     // --quick Table 1: side / 8, rays / 64
constexpr uint32_t kFullScalingDivisor = 8;    // section 5.2: 4096² → 512² = 262,144 rays
constexpr uint32_t kQuickScalingDivisor = 32;  // --quick section 5.2: 128² = 16,384 rays

struct Options {
  bool quick = false, json = false, no_baselines = false, no_scaling = false;
  int threads = 0;
  int side_divisor = 0;  // testing: overrides every divisor and repeats nothing
  std::string isa = "auto", models, pretest = "auto";
};

double gtests(double tests, const Timing& t) { return t.seconds > 0 ? tests / t.seconds / 1e9 : 0; }

std::vector<const PaperModel*> chosen_models(const std::string& list) {
  std::vector<const PaperModel*> out;
  if (list.empty()) {
    for (const PaperModel& m : kPaperTable1) out.push_back(&m);
    return out;
  }
  std::stringstream ss(list);
  for (std::string name; std::getline(ss, name, ',');) {
    const PaperModel* found = nullptr;
    for (const PaperModel& m : kPaperTable1)
      if (name == m.name) found = &m;
    if (!found) throw InputError("--models: unknown model '" + name + "' (mod1 .. mod17)");
    out.push_back(found);
  }
  return out;
}

void print_table1(const std::vector<Table1Result>& rows, uint32_t divisor, int ranks) {
  if (ranks > 1)
    std::printf(
        "\nTable 1 across %d ranks (each rank one thread on a contiguous share of every row's rays; "
        "seconds: the slowest rank's median thread CPU time; t/c vm per rank)%s\n",
        ranks,
        divisor > 1 ? (" — rays scaled: image side / " + std::to_string(divisor) + ", rays / " +
                       std::to_string(divisor * divisor) + " (approx.)")
                          .c_str()
                    : " — full paper sizes");
  else
    std::printf("\nTable 1 (one thread; seconds: median thread CPU time)%s\n",
                divisor > 1 ? (" — rays scaled: image side / " + std::to_string(divisor) + ", rays / " +
                               std::to_string(divisor * divisor) + " (approx.)")
                                  .c_str()
                            : " — full paper sizes");
  std::printf("%-6s %9s %6s | %9s %9s %9s %9s | %8s %8s | %8s %8s | %6s %6s %6s %6s | %5s %5s %6s | %s\n",
              "model", "rays", "tris", "original", "optimized", "vec-paper", "vec-mt", "orig/vec", "opt/vec",
              "paper o/v", "paper p/v", "G/s o", "G/s p", "G/s vp", "G/s vm", "GHz", "FMA/c", "t/c vm",
              "mismatch");
  double sum_o = 0, sum_p = 0, sum_po = 0, sum_pp = 0;
  int n = 0;
  for (const Table1Result& r : rows) {
    const double so = r.original.seconds / r.vec_paper.seconds;
    const double sp = r.optimized.seconds / r.vec_paper.seconds;
    if (r.baselines) {
      std::printf(
          "%-6s %9llu %6u | %9.4f %9.4f %9.4f %9.4f | %8.2f %8.2f | %8.2f %8.2f | %6.3f %6.3f "
          "%6.2f %6.2f | %5.2f %5.2f %6.2f | %llu\n",
          r.model.name, (unsigned long long)r.rays(), r.model.triangles, r.original.seconds,
          r.optimized.seconds, r.vec_paper.seconds, r.vec_mt.seconds, so, sp, r.model.speedup_original,
          r.model.speedup_optimized, gtests(r.tests(), r.original), gtests(r.tests(), r.optimized),
          gtests(r.tests(), r.vec_paper), gtests(r.tests(), r.vec_mt), r.vec_mt.ghz, r.vec_mt.fma_per_cycle,
          r.vec_mt.tests_per_cycle(r.tests_per_rank()), (unsigned long long)r.mismatches);
      sum_o += so, sum_p += sp, sum_po += r.model.speedup_original, sum_pp += r.model.speedup_optimized, ++n;
    } else {
      std::printf(
          "%-6s %9llu %6u | %9s %9s %9.4f %9.4f | %8s %8s | %8.2f %8.2f | %6s %6s %6.2f "
          "%6.2f | %5.2f %5.2f %6.2f | -\n",
          r.model.name, (unsigned long long)r.rays(), r.model.triangles, "-", "-", r.vec_paper.seconds,
          r.vec_mt.seconds, "-", "-", r.model.speedup_original, r.model.speedup_optimized, "-", "-",
          gtests(r.tests(), r.vec_paper), gtests(r.tests(), r.vec_mt), r.vec_mt.ghz, r.vec_mt.fma_per_cycle,
          r.vec_mt.tests_per_cycle(r.tests_per_rank()));
    }
  }
  if (n > 0)
    std::printf(
        "mean speedup (arithmetic, as the paper): original/vectorized %.2f (paper %.2f), "
        "optimized/vectorized %.2f (paper %.2f)\n",
        sum_o / n, sum_po / n, sum_p / n, sum_pp / n);
  std::printf(
      "vec-paper and vec-mt: the vectorized brute force with the paper's arithmetic and with "
      "rayvec's default `mt`; speedups use vec-paper (the paper's vectorized version).\n");
  std::printf(
      "vectorized columns: median of at least %d runs; GHz: the core clock measured before "
      "each vec-mt run (dependent-add chain), FMA/c: vector FMAs per cycle a throughput probe "
      "got before each vec-mt run (2.00 = an uncontended core with two FMA pipes; lower = the "
      "vector pipes are shared, e.g. with a VM neighbour, or, when only --isa avx512 reads about 1 "
      "and --isa avx2 still 2, the core runs 512-bit operations as two 256-bit halves; t/c drops "
      "with it), t/c vm: "
      "vec-mt ray-triangle tests per cycle.\n",
      kVectorizedMinRuns);
}

void print_scaling(const std::vector<ScalingResult>& rows, uint32_t divisor, int ranks) {
  if (rows.empty()) return;
  const uint32_t side = rows.front().side;
  std::printf(
      "\nThread scaling (section 5.2): 16,777,216 rays scaled to %u (image side 4096 / %u = "
      "%u, rays / %u)\n",
      side * side, divisor, side, divisor * divisor);
  if (ranks > 1)
    std::printf(
        "across %d ranks: ranks x threads workers, each rank its share of the rays (rays per rank: %s); "
        "the ranks start each run together and a run takes the slowest rank's wall-clock seconds, "
        "median; speedup against %d ranks x 1 thread\n",
        ranks, join_counts(rows.front().rank_rays).c_str(), ranks);
  else
    std::printf("(wall-clock seconds, median)\n");
  std::printf("%6s %-11s %7s %9s %8s %8s %9s%s\n", "tris", "intersector", "threads", "seconds", "speedup",
              "G/s", "mismatch", ranks > 1 ? " | imbalance, rank seconds" : "");
  double base = 0;
  for (const ScalingResult& r : rows) {
    if (r.threads == 1) base = r.time.seconds;
    const double tests = double(r.side) * r.side * r.triangles;
    std::printf("%6u %-11s %7u %9.4f %8.2f %8.2f %9llu", r.triangles, intersector_name(r.intersector),
                r.threads, r.time.seconds, base / r.time.seconds, gtests(tests, r.time),
                (unsigned long long)r.mismatches);
    if (ranks > 1)
      std::printf(" | %.3f: %s", slowest_over_mean(r.rank_seconds), join_seconds(r.rank_seconds).c_str());
    std::printf("\n");
  }
}

void print_json(const Options& o, Isa isa, int threads, int ranks, uint32_t table_divisor,
                uint32_t scaling_divisor, const std::vector<Table1Result>& table,
                const std::vector<ScalingResult>& scaling, uint64_t mismatches) {
  std::printf(
      "{\"cpu\":%s,\"isa\":%s,\"mt_pretest\":%s,\"threads\":%d,\"ranks\":%d,\"quick\":%s,"
      "\"table1_side_divisor\":%u,\"scaling_side_divisor\":%u,\"table1\":[",
      json_string(cpu_features().brand).c_str(), json_string(isa_name(isa)).c_str(),
      json_string(mt_pretest_name(mt_pretest_in_use(isa))).c_str(), threads, ranks,
      o.quick ? "true" : "false", table_divisor, scaling_divisor);
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Table1Result& r = table[i];
    std::printf(
        "%s{\"model\":%s,\"rays\":%llu,\"paper_rays\":%u,\"triangles\":%u,"
        "\"seconds\":{\"vectorized_paper\":%.6g,\"vectorized_mt\":%.6g",
        i ? "," : "", json_string(r.model.name).c_str(), (unsigned long long)r.rays(), r.model.rays,
        r.model.triangles, r.vec_paper.seconds, r.vec_mt.seconds);
    if (r.baselines)
      std::printf(
          ",\"original\":%.6g,\"optimized\":%.6g},\"speedup\":{\"original\":%.4g,"
          "\"optimized\":%.4g",
          r.original.seconds, r.optimized.seconds, r.original.seconds / r.vec_paper.seconds,
          r.optimized.seconds / r.vec_paper.seconds);
    std::printf(
        "},\"clock_ghz\":{\"vectorized_paper\":%.4g,\"vectorized_mt\":%.4g},"
        "\"fma_per_cycle\":{\"vectorized_paper\":%.4g,\"vectorized_mt\":%.4g},"
        "\"tests_per_cycle\":{\"vectorized_paper\":%.4g,\"vectorized_mt\":%.4g},"
        "\"repeats\":{\"vectorized_paper\":%d,\"vectorized_mt\":%d}",
        r.vec_paper.ghz, r.vec_mt.ghz, r.vec_paper.fma_per_cycle, r.vec_mt.fma_per_cycle,
        r.vec_paper.tests_per_cycle(r.tests_per_rank()), r.vec_mt.tests_per_cycle(r.tests_per_rank()),
        r.vec_paper.repeats, r.vec_mt.repeats);
    std::printf(",\"gtests_per_s\":{\"vectorized_paper\":%.4g,\"vectorized_mt\":%.4g",
                gtests(r.tests(), r.vec_paper), gtests(r.tests(), r.vec_mt));
    if (r.baselines)
      std::printf(",\"original\":%.4g,\"optimized\":%.4g", gtests(r.tests(), r.original),
                  gtests(r.tests(), r.optimized));
    std::printf(
        "},\"paper\":{\"original\":%g,\"optimized\":%g,\"vectorized\":%g,"
        "\"speedup_original\":%g,\"speedup_optimized\":%g},\"mismatches\":%llu,"
        "\"mt_differences\":%llu,\"hits\":%llu,\"checksum\":\"0x%016llx\"",
        r.model.original_s, r.model.optimized_s, r.model.vectorized_s, r.model.speedup_original,
        r.model.speedup_optimized, (unsigned long long)r.mismatches, (unsigned long long)r.mt_differences,
        (unsigned long long)r.hits, (unsigned long long)r.checksum);
    if (ranks > 1) print_json_shares(r);
    std::printf("}");
  }
  std::printf("],\"scaling\":[");
  for (std::size_t i = 0; i < scaling.size(); ++i) {
    const ScalingResult& r = scaling[i];
    std::printf(
        "%s{\"rays\":%llu,\"triangles\":%u,\"intersector\":%s,\"threads\":%u,"
        "\"seconds\":%.6g,\"mismatches\":%llu",
        i ? "," : "", (unsigned long long)(uint64_t(r.side) * r.side), r.triangles,
        json_string(intersector_name(r.intersector)).c_str(), r.threads, r.time.seconds,
        (unsigned long long)r.mismatches);
    if (ranks > 1)
      std::printf(",\"rank_rays\":[%s],\"rank_seconds\":[%s],\"imbalance\":%.4g",
                  join_counts(r.rank_rays).c_str(), join_seconds(r.rank_seconds).c_str(),
                  slowest_over_mean(r.rank_seconds));
    std::printf("}");
  }
  std::printf("],\"mismatches\":%llu}\n", (unsigned long long)mismatches);
}

int run(const Options& o) {
  Isa isa;
  if (const std::string err = resolve_isa(o.isa, isa); !err.empty()) throw InputError("--isa: " + err);
  check_threads_option(o.threads);
  if (o.side_divisor < 0) throw InputError("--side-divisor: must be 1 or more");
  if (o.pretest == "sign")
    set_mt_pretest(MtPretest::sign_bits);
  else if (o.pretest == "ordered")
    set_mt_pretest(MtPretest::ordered_compares);
  else if (o.pretest != "auto")
    throw InputError("--pretest: '" + o.pretest + "' is not auto, sign or ordered");
  const auto models = chosen_models(o.models);
  // Under mpirun every rank has checked the options by now: a bad one stops every rank here, with
  // its message once. The scaling run's thread counts must be the same on every rank: the fewest
  // cores any rank has, unless --threads says.
  Cluster& ranks = cluster();
  ranks.begin_collective();
  std::vector<int64_t> fewest{-int64_t(o.threads > 0 ? o.threads : omp_get_num_procs())};
  ranks.all_max(fewest);
  const int threads = int(-fewest[0]);
  const bool testing = o.side_divisor > 0;
  const uint32_t table_divisor = testing ? o.side_divisor : (o.quick ? kQuickTableDivisor : 1);
  const uint32_t scaling_divisor =
      testing ? o.side_divisor : (o.quick ? kQuickScalingDivisor : kFullScalingDivisor);
  const double min_seconds = testing ? 0.0 : (o.quick ? 0.05 : 0.2);

  if (!o.json && ranks.root()) {
    std::printf("rayvec bench paper: Sena et al. (2018), Table 1 and section 5.2, on a generated scene\n");
    std::printf(
        "cpu: %s\nisa: %s (%d floats per step; mt pre-test: %s%s)\nthreads: %d (Table 1 runs on one "
        "thread)\n",
        cpu_features().brand.c_str(), isa_name(isa), triangle_kernels(isa, Intersector::mt).width,
        mt_pretest_name(mt_pretest_in_use(isa)), o.pretest == "auto" ? ", this CPU's default" : ", --pretest",
        threads);
    if (ranks.distributed())
      std::printf(
          "ranks: %d (every rank traces a contiguous share of each row's rays; cpu and isa are rank "
          "0's)\n",
          ranks.size());
    std::printf(
        "scene: triangles with vertices uniform in [0,1)^3 (SplitMix64, seed 0x%llx); "
        "rays of a pinhole camera at (0.5,0.5,-1.5) through the cube's front face "
        "(docs/benchmarks.md)\n",
        (unsigned long long)kPaperSceneSeed);
    std::fflush(stdout);
  }
  const StageLine stages("bench paper");
  const Progress progress = stages.progress();

  std::vector<Table1Result> table;
  uint64_t mismatches = 0;
  for (const PaperModel* m : models) {
    table.push_back(table1_row_across_ranks(ranks, *m, scaled_side(m->rays, table_divisor), isa,
                                            !o.no_baselines, min_seconds, progress));
    mismatches += table.back().mismatches;
  }
  std::vector<ScalingResult> scaling;
  if (!o.no_scaling) {
    const uint32_t side = scaled_side(kPaperScalingSide * kPaperScalingSide, scaling_divisor);
    for (uint32_t tris : kPaperScalingTriangles)
      for (Intersector in : {Intersector::paper, Intersector::mt})
        for (const ScalingResult& r :
             scaling_across_ranks(ranks, side, tris, isa, in, threads, min_seconds, progress)) {
          scaling.push_back(r);
          mismatches += r.mismatches;
        }
  }
  stages.clear();
  if (!ranks.root()) return 0;  // rank 0 prints for all

  if (o.json) {
    print_json(o, isa, threads, ranks.size(), table_divisor, scaling_divisor, table, scaling, mismatches);
  } else {
    print_table1(table, table_divisor, ranks.size());
    print_hits(table, ranks.size());
    print_scaling(scaling, scaling_divisor, ranks.size());
    std::printf(
        "\nmismatches (ids or t differing between original, optimized and vectorized paper; "
        "or between thread counts%s): %llu\n",
        ranks.distributed() ? "; or between the gathered hits and rank 0's" : "",
        (unsigned long long)mismatches);
  }
  if (mismatches > 0) {
    std::fprintf(stderr, "rayvec: bench paper: %llu mismatching results\n", (unsigned long long)mismatches);
    return 1;
  }
  return 0;
}

}  // namespace

void register_bench_paper_command(Command& bench) {
  static Options o;
  bench.subcommand("paper", "Reproduce Sena et al. (2018): Table 1 and the thread-scaling run")
      .flag("--quick", o.quick, "scaled-down rays (Table 1: rays / 64; scaling: rays / 1024), < 1 min")
      .option("--threads", o.threads, "most threads for the scaling run, 0 to 1024 (0 = all cores)")
      .flag("--json", o.json, "print one JSON object instead of tables")
      .option("--isa", o.isa, "vectorized ISA: auto, scalar, avx2 or avx512")
      .option("--models", o.models, "only these Table 1 rows, e.g. mod2,mod7")
      .flag("--no-baselines", o.no_baselines, "skip original and optimized (vectorized only)")
      .flag("--no-scaling", o.no_scaling, "skip the thread-scaling run")
      .option("--pretest", o.pretest,
              "tuning: the mt kernels' pre-test, auto (this CPU's default), sign or ordered (the same hits; "
              "docs/benchmarks.md#decision-sign-pretest)")
      .option("--side-divisor", o.side_divisor,
              "testing: divide every image side by this and time each run once")
      .footer(
          "Scene and method: docs/benchmarks.md. Exit status 1 if versions disagree.\n"
          "Under mpirun (an MPI build) every rank times a share of each row's rays and rank 0 gathers\n"
          "the hits, the same as one process's (docs/distributed.md).\n"
          "Examples:\n"
          "  rayvec bench paper --quick\n"
          "  mpirun -np 2 rayvec bench paper --models mod2 --no-baselines --no-scaling")
      .run([] { return run(o); });
}

}  // namespace rayvec
