#include "accuracy/accuracy_report.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <limits>
#include <memory>
#include <random>

#include "bench/median.h"
#include "bench/ray_sets.h"
#include "platform/isa.h"
#include "platform/stopwatch.h"

namespace rayvec {

namespace {

// Wall time; with one OpenMP thread the calling thread's CPU time instead (the run happens on it),
// which stays stable while other processes share the cores (as `bench rays` does).
double seconds_of(const std::function<void()>& run) {
  if (omp_get_max_threads() == 1) {
    timespec t0{}, t1{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
    run();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
    return double(t1.tv_sec - t0.tv_sec) + 1e-9 * double(t1.tv_nsec - t0.tv_nsec);
  }
  const auto t0 = std::chrono::steady_clock::now();
  run();
  return seconds_since(t0);
}

RayBatch batch_of(const std::vector<Ray>& rays) {
  RayBatch b;
  b.reserve(rays.size());
  for (const Ray& r : rays) b.push_back(r);
  return b;
}

// 1,000 random triangles and 4,096 random rays through them: the brute-force throughput scene.
void brute_scene(uint64_t seed, TriangleMesh& mesh, std::vector<Ray>& rays) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int k = 0; k < 1000; ++k) {
    const Vec3f c{u(rng), u(rng), u(rng)};
    mesh.add_triangle({c.x + 0.1f * u(rng), c.y + 0.1f * u(rng), c.z + 0.1f * u(rng)},
                      {c.x + 0.1f * u(rng), c.y + 0.1f * u(rng), c.z + 0.1f * u(rng)},
                      {c.x + 0.1f * u(rng), c.y + 0.1f * u(rng), c.z + 0.1f * u(rng)});
  }
  for (int k = 0; k < 4096; ++k)
    rays.push_back(Ray{{3 * u(rng), 3 * u(rng), -3}, {0.3f * u(rng), 0.3f * u(rng), 1}});
}

double pct(std::size_t n, std::size_t of) { return of ? 100.0 * double(n) / double(of) : 0.0; }

struct Totals {
  std::size_t rays = 0, oracle_hits = 0, fm = 0, fh = 0, wn = 0, nan = 0, crossing_fm = 0;
};
Totals totals(const AccuracyReport& r, const ModeResult& m, bool include_control) {
  Totals t;
  for (std::size_t f = 0; f < m.families.size(); ++f) {
    if (!include_control && r.families[f] == "random_control") continue;
    const FamilyScore& s = m.families[f];
    t.rays += s.rays;
    t.oracle_hits += s.oracle_hits;
    t.fm += s.false_misses;
    t.fh += s.false_hits;
    t.wn += s.wrong_nearest;
    t.nan += s.nan_outputs;
    if (r.family_crossing[f]) t.crossing_fm += s.false_misses;
  }
  return t;
}

const ModeResult* find(const AccuracyReport& r, Intersector in, Isa isa) {
  for (const ModeResult& m : r.modes)
    if (m.intersector == in && m.isa == isa) return &m;
  return nullptr;
}

// Median over repeats of other[k] / base[k]: the time ratio of two modes, paired by repeat.
double paired_ratio(const std::vector<double>& other, const std::vector<double>& base) {
  std::vector<double> r;
  for (std::size_t k = 0; k < other.size() && k < base.size(); ++k)
    if (base[k] > 0) r.push_back(other[k] / base[k]);
  return median(r);
}

std::size_t family_index(const AccuracyReport& r, const char* name) {
  for (std::size_t f = 0; f < r.families.size(); ++f)
    if (r.families[f] == name) return f;
  return 0;
}

// The paragraph a student can follow, with this run's numbers (best ISA).
void write_student_summary(const AccuracyReport& r, std::FILE* out) {
  const Isa isa = best_isa();
  const ModeResult *paper = find(r, Intersector::paper, isa), *mt = find(r, Intersector::mt, isa),
                   *mt64 = find(r, Intersector::mt64, isa), *wt = find(r, Intersector::watertight, isa),
                   *w64 = find(r, Intersector::watertight64, isa);
  if (!paper || !mt || !mt64 || !wt || !w64) return;
  std::size_t crossing_rays = 0;
  for (std::size_t f = 0; f < r.families.size(); ++f)
    if (r.family_crossing[f]) crossing_rays += mt->families[f].oracle_hits;
  const std::size_t tiny = family_index(r, "tiny_closed");
  auto extra = [](const std::vector<double>& other, const std::vector<double>& base) {
    return 100.0 * (paired_ratio(other, base) - 1.0);
  };
  const Totals tp = totals(r, *paper, false), tm = totals(r, *mt, false), t64 = totals(r, *mt64, false),
               tw = totals(r, *wt, false), tw64 = totals(r, *w64, false);
  std::fprintf(
      out,
      "\n## What each mode gets wrong, and what fixing it costs (%s)\n\n"
      "A float intersector decides on rounded numbers, so near an edge it can answer for a ray that\n"
      "passes just beside the exact one. **paper** (Sena et al. 2018) also rejects |det| < 1e-6 and\n"
      "t <= 1e-6 in absolute terms: %.0f%% of the rays at the tiny closed spheres are missed, and\n"
      " %zu of %zu crossing rays slip through a closed mesh. **mt** drops the\n"
      "epsilons but still computes each triangle's edge test from its own rounded edges, so two\n"
      "neighbours can both say \"not mine\" for a ray through their shared edge or vertex: %zu of %zu\n"
      "crossing rays leak through (a renderer shows them as speckles of background). **mt64** repeats mt in\n"
      "double: %zu leaks, far fewer but not zero. **watertight** (Woop et al. 2013) computes the\n"
      "shared edge identically for both neighbours, so no crossing ray leaks (%zu); what remains is\n"
      "choosing the neighbour across an edge (%.1f%% of hits are not on the exact nearest triangle)\n"
      "and float-sized errors at open edges and grazing angles (%.2f%% false misses, %.2f%% false\n"
      "hits over all families). It costs %+.1f%% time on BVH primary rays over mt (target <= 10%%)\n"
      "and %+.1f%% in brute force. **watertight64** does the same in double: %zu wrong answers in\n"
      "%zu hard-case rays in this run, for %+.1f%% BVH time (%+.1f%% brute force) over mt (in a BVH\n"
      "the box tests take much of the time; the brute-force ratio is the kernel's own cost). Totals of\n"
      "wrong answers (miss + false hit + wrong nearest): paper %zu, mt %zu, mt64 %zu, watertight\n"
      "%zu, watertight64 %zu. Scalar mt/mt64 differ from their SIMD versions (no FMA in baseline\n"
      "x86-64); the watertight modes use no FMA and give the same ids on every ISA.\n",
      isa_name(isa), pct(paper->families[tiny].false_misses, paper->families[tiny].oracle_hits),
      tp.crossing_fm, crossing_rays, tm.crossing_fm, crossing_rays, t64.crossing_fm, tw.crossing_fm,
      pct(tw.wn, tw.oracle_hits), pct(tw.fm, tw.oracle_hits), pct(tw.fh, tw.rays - tw.oracle_hits),
      extra(wt->bvh_seconds, mt->bvh_seconds), extra(wt->brute_seconds, mt->brute_seconds),
      tw64.fm + tw64.fh + tw64.wn, tw64.rays, extra(w64->bvh_seconds, mt->bvh_seconds),
      extra(w64->brute_seconds, mt->brute_seconds), tp.fm + tp.fh + tp.wn, tm.fm + tm.fh + tm.wn,
      t64.fm + t64.fh + t64.wn, tw.fm + tw.fh + tw.wn, tw64.fm + tw64.fh + tw64.wn);
}

}  // namespace

AccuracyReport measure_accuracy(const AccuracySettings& settings, std::FILE* log) {
  AccuracyReport report;
  report.settings = settings;
  report.threads = omp_get_max_threads();
  report.cpu = cpu_features().brand;

  std::vector<HardCaseFamily> families = hard_case_families(settings.seed, settings.scale);
  families.push_back(random_control_family(settings.seed, settings.scale));
  std::vector<std::vector<ExactHit>> truth;
  for (const HardCaseFamily& f : families) {
    if (log) std::fprintf(log, "accuracy: oracle for %s (%zu rays)\n", f.name.c_str(), f.rays.size());
    truth.push_back(oracle_closest(f));
    report.families.push_back(f.name);
    report.family_descriptions.push_back(f.description);
    report.family_crossing.push_back(f.crossing);
  }

  TriangleMesh brute_mesh;
  std::vector<Ray> brute_rays;
  brute_scene(settings.seed, brute_mesh, brute_rays);
  const RayBatch brute_batch = batch_of(brute_rays);
  report.brute_triangles = brute_mesh.size();
  report.brute_rays = brute_rays.size();

  // BVH primary rays as in `bench rays` (ray_sets.h), on a generated 81,920-triangle sphere.
  const TriangleMesh sphere = make_icosphere({0, 0, 0}, 1.0, 6, settings.seed);
  report.bvh_triangles = sphere.size();
  const BenchCamera cam = frame_mesh(sphere, settings.bvh_size, settings.bvh_size);
  const RayBatch primary = batch_of(primary_rays(cam).rays);
  // The same rays with a NaN or Inf in one field each (the non-finite guard must cost no more than 2.5×).
  RayBatch poisoned = primary;
  for (std::size_t i = 0; i < poisoned.size(); ++i) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    switch (i % 4) {
      case 0: poisoned.dx[i] = nan; break;
      case 1: poisoned.oz[i] = kInf; break;
      case 2: poisoned.dy[i] = -kInf; break;
      default: poisoned.tmin[i] = nan; break;
    }
  }

  // Timings: per ISA, every intersector's run is interleaved with the others' in each repeat, so
  // load from other processes hits them alike and the ratios (watertight / mt) stay meaningful.
  for (Isa isa : supported_isas()) {
    if (log) std::fprintf(log, "accuracy: timing %s\n", isa_name(isa));
    const std::size_t n_in = std::size(kAllIntersectors);
    std::vector<std::unique_ptr<Accelerator>> brute(n_in), bvh(n_in);
    for (std::size_t k = 0; k < n_in; ++k) {
      const TraceConfig cfg{isa, kAllIntersectors[k]};
      brute[k] = make_accelerator(AccelKind::brute, brute_mesh, cfg);
      try {
        bvh[k] = make_accelerator(AccelKind::bvh, sphere, cfg);
      } catch (const std::exception&) {
        bvh[k] = nullptr;  // BVH not available in this build
      }
    }
    std::vector<std::vector<double>> tb(n_in), tv(n_in), tn(n_in);
    std::vector<Hit> hb(brute_batch.size()), hv(primary.size());
    for (int rep = 0; rep <= settings.repeats; ++rep)  // rep 0: warm-up, not recorded
      for (std::size_t k = 0; k < n_in; ++k) {
        const double b = seconds_of([&] { trace_closest(*brute[k], brute_batch, hb); });
        if (rep > 0) tb[k].push_back(b);
        if (!bvh[k]) continue;
        const double v = seconds_of([&] { trace_closest(*bvh[k], primary, hv); });
        if (rep > 0) tv[k].push_back(v);
        const double w = seconds_of([&] { trace_closest(*bvh[k], poisoned, hv); });
        if (rep > 0) tn[k].push_back(w);
      }
    for (std::size_t k = 0; k < n_in; ++k) {
      ModeResult m;
      m.intersector = kAllIntersectors[k];
      m.isa = isa;
      m.brute_gtests = double(brute_batch.size()) * double(brute_mesh.size()) / median(tb[k]) * 1e-9;
      if (bvh[k]) m.bvh_mrays = double(primary.size()) / median(tv[k]) * 1e-6;
      m.brute_seconds = tb[k];
      m.bvh_seconds = tv[k];
      m.bvh_nonfinite_seconds = tn[k];
      report.modes.push_back(std::move(m));
    }
  }
  // Accuracy of every mode on every family (brute force: the BVH returns the same hits, tested).
  for (ModeResult& m : report.modes) {
    if (log)
      std::fprintf(log, "accuracy: scoring %s / %s\n", intersector_name(m.intersector), isa_name(m.isa));
    for (std::size_t f = 0; f < families.size(); ++f) {
      const auto accel = make_accelerator(AccelKind::brute, families[f].mesh, {m.isa, m.intersector});
      const RayBatch rays = batch_of(families[f].rays);
      std::vector<Hit> hits(rays.size());
      trace_closest(*accel, rays, hits);
      m.families.push_back(score_family(truth[f], hits));
    }
  }
  // Report in intersector-major order.
  std::stable_sort(report.modes.begin(), report.modes.end(), [](const ModeResult& a, const ModeResult& b) {
    return int(a.intersector) < int(b.intersector);
  });
  return report;
}

void write_accuracy_markdown(const AccuracyReport& r, std::FILE* out) {
  const Isa best = best_isa();
  std::fprintf(
      out,
      "# Accuracy versus time\n\n"
      "Generated by `rayvec accuracy -o docs/accuracy.md` (do not edit by hand; the plot is drawn by\n"
      "`scripts/plot_accuracy.py` from `rayvec accuracy --json`). Machine: %s, %d OpenMP threads.\n"
      "Every ray of every family is judged against an exact oracle (GMP rationals,\n"
      "`src/accuracy/exact_oracle.h`): a hit is a unique intersection with the closed triangle,\n"
      "tmin <= t <= tmax; degenerate triangles, coplanar rays and non-finite input never hit.\n"
      "Timings are medians of %d runs on a shared 2-core machine (%s; compare ratios within a\n"
      "row set rather than absolute numbers across runs).\n\n",
      r.cpu.c_str(), r.threads, r.settings.repeats,
      r.threads == 1 ? "one thread: the thread's CPU-time clock, stable under load"
                     : "wall clock: noisy when others share the cores");
  std::fprintf(
      out,
      "## Summary\n\n"
      "Brute force: %zu rays × %zu random triangles. BVH: the primary rays of `bench rays` "
      "(%d×%d, ray_sets.h) on a %zu-triangle sphere. Rates over all hard-case families (random\n"
      "control excluded): false miss = %% of the rays the oracle says hit; false hit = %% of the rays\n"
      "it says miss; wrong nearest = %% of oracle hits answered with a triangle that is not at the\n"
      "exact nearest t (usually the neighbour across an edge). Crossing misses = false misses on the\n"
      "families whose rays all cross a closed surface (watertight modes must have 0).\n\n"
      "| intersector | ISA | brute G tests/s | BVH primary Mrays/s | crossing misses | false miss %% | false "
      "hit %% | wrong nearest %% | NaN outputs |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|\n",
      r.brute_rays, r.brute_triangles, r.settings.bvh_size, r.settings.bvh_size, r.bvh_triangles);
  for (const ModeResult& m : r.modes) {
    const Totals t = totals(r, m, false);
    char bvh[32] = "n/a";
    if (m.bvh_mrays > 0) std::snprintf(bvh, sizeof bvh, "%.1f", m.bvh_mrays);
    std::fprintf(out, "| %s | %s | %.3f | %s | %zu | %.2f | %.2f | %.2f | %zu |\n",
                 intersector_name(m.intersector), isa_name(m.isa), m.brute_gtests, bvh, t.crossing_fm,
                 pct(t.fm, t.oracle_hits), pct(t.fh, t.rays - t.oracle_hits), pct(t.wn, t.oracle_hits),
                 t.nan);
  }
  std::fprintf(out,
               "\n## Cost of watertightness (time relative to mt; median over repeats of the ratio of "
               "back-to-back runs)\n\n"
               "| ISA | BVH watertight | brute watertight | BVH watertight64 | brute watertight64 "
               "|\n|---|---:|---:|---:|---:|\n");
  for (Isa isa : supported_isas()) {
    const ModeResult *mt = find(r, Intersector::mt, isa), *wt = find(r, Intersector::watertight, isa),
                     *w64 = find(r, Intersector::watertight64, isa);
    if (!mt || !wt || !w64) continue;
    std::fprintf(
        out, "| %s | %.3f× | %.3f× | %.3f× | %.3f× |\n", isa_name(isa),
        paired_ratio(wt->bvh_seconds, mt->bvh_seconds), paired_ratio(wt->brute_seconds, mt->brute_seconds),
        paired_ratio(w64->bvh_seconds, mt->bvh_seconds), paired_ratio(w64->brute_seconds, mt->brute_seconds));
  }
  std::fprintf(out,
               "\n## Non-finite rays (BVH time of the primary rays with a NaN or Inf in one field "
               "each, relative to the same rays finite; issue limit 2.5×)\n\n| intersector |");
  for (Isa isa : supported_isas()) std::fprintf(out, " %s |", isa_name(isa));
  std::fprintf(out, "\n|---|");
  for (std::size_t k = 0; k < supported_isas().size(); ++k) std::fprintf(out, "---:|");
  std::fprintf(out, "\n");
  for (Intersector in : kAllIntersectors) {
    std::fprintf(out, "| %s |", intersector_name(in));
    for (Isa isa : supported_isas()) {
      const ModeResult* m = find(r, in, isa);
      std::fprintf(out, " %.2f× |", m ? paired_ratio(m->bvh_nonfinite_seconds, m->bvh_seconds) : 0.0);
    }
    std::fprintf(out, "\n");
  }
  std::fprintf(
      out,
      "\n## Per family (ISA %s; cells: false miss %% / false hit %% / wrong nearest %%)\n\n| family | rays |",
      isa_name(best));
  for (Intersector in : kAllIntersectors) std::fprintf(out, " %s |", intersector_name(in));
  std::fprintf(out, "\n|---|---:|");
  for (std::size_t k = 0; k < std::size(kAllIntersectors); ++k) std::fprintf(out, "---|");
  std::fprintf(out, "\n");
  for (std::size_t f = 0; f < r.families.size(); ++f) {
    std::fprintf(out, "| %s%s |", r.families[f].c_str(), r.family_crossing[f] ? " (crossing)" : "");
    bool first = true;
    for (Intersector in : kAllIntersectors) {
      const ModeResult* m = find(r, in, best);
      if (!m) continue;
      const FamilyScore& s = m->families[f];
      if (first) std::fprintf(out, " %zu |", s.rays);
      first = false;
      std::fprintf(out, " %.1f / %.1f / %.1f |", pct(s.false_misses, s.oracle_hits),
                   pct(s.false_hits, s.rays - s.oracle_hits), pct(s.wrong_nearest, s.oracle_hits));
    }
    std::fprintf(out, "\n");
  }
  write_student_summary(r, out);
  std::fprintf(out, "\n### Families\n\n");
  for (std::size_t f = 0; f < r.families.size(); ++f)
    std::fprintf(out, "- `%s`: %s.\n", r.families[f].c_str(), r.family_descriptions[f].c_str());
  std::fprintf(out, "\n![cost against error](images/accuracy_cost_vs_error.png)\n");
}

void write_accuracy_json(const AccuracyReport& r, std::FILE* out) {
  std::fprintf(out, "{\"cpu\":\"%s\",\"threads\":%d,\"scale\":%d,\"bvh_size\":%d,\"families\":[",
               r.cpu.c_str(), r.threads, r.settings.scale, r.settings.bvh_size);
  for (std::size_t f = 0; f < r.families.size(); ++f)
    std::fprintf(out, "%s{\"name\":\"%s\",\"crossing\":%s}", f ? "," : "", r.families[f].c_str(),
                 r.family_crossing[f] ? "true" : "false");
  std::fprintf(out, "],\"modes\":[");
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const ModeResult& m = r.modes[k];
    const ModeResult* mt = find(r, Intersector::mt, m.isa);
    std::fprintf(out,
                 "%s{\"intersector\":\"%s\",\"isa\":\"%s\",\"brute_gtests_per_s\":%.6f,"
                 "\"bvh_primary_mrays_per_s\":%.6f,\"brute_time_vs_mt\":%.4f,\"bvh_time_vs_mt\":%.4f,"
                 "\"families\":[",
                 k ? "," : "", intersector_name(m.intersector), isa_name(m.isa), m.brute_gtests, m.bvh_mrays,
                 mt ? paired_ratio(m.brute_seconds, mt->brute_seconds) : 0.0,
                 mt ? paired_ratio(m.bvh_seconds, mt->bvh_seconds) : 0.0);
    for (std::size_t f = 0; f < m.families.size(); ++f) {
      const FamilyScore& s = m.families[f];
      std::fprintf(out,
                   "%s{\"name\":\"%s\",\"rays\":%zu,\"oracle_hits\":%zu,\"false_misses\":%zu,"
                   "\"false_hits\":%zu,\"wrong_nearest\":%zu,\"nan_outputs\":%zu}",
                   f ? "," : "", r.families[f].c_str(), s.rays, s.oracle_hits, s.false_misses, s.false_hits,
                   s.wrong_nearest, s.nan_outputs);
    }
    std::fprintf(out, "]}");
  }
  std::fprintf(out, "]}\n");
}

}  // namespace rayvec
