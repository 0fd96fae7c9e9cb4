// `rayvec bench rays MODEL.obj`: BVH build time, bytes per triangle, and Mrays/s of primary (single
// rays and 4×4 packets), shadow (any-hit, single rays and packets) and incoherent rays, optionally against
// Embree 3 in the same run. The ray sets are defined in src/bench/ray_sets.h, the timing in rays_bench.h.
#include <omp.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "accel/bvh_accelerator.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "app/trace_options.h"
#include "bench/cpu_clock.h"
#include "bench/fma_rate.h"
#include "bench/median.h"
#include "bench/rays_bench.h"
#include "io/input_error.h"
#include "io/json_string.h"
#include "io/progress.h"
#include "platform/stopwatch.h"
#include "scene/obj_loader.h"

namespace rayvec {
namespace {

struct Options {
  std::string model, size = "1024x1024";
  TraceOptions trace;
  bool json = false, vs_embree = false;
  int repeats = 5, width = 0;
  int max_leaf = 0, leaf_block = 0;  // 0: the builder's defaults
  int leaf_steps = 0;                // 0: default_leaf_steps
  int leaf_call = -1;                // -1: default_leaf_call, else a LeafCall
  int merge_steps = BvhOptions{}.merge_steps;
  int builds = 3;  // builds timed; the median is reported
  double split_budget = SahConfig{}.split_budget;
  int stored_normals = BvhOptions{}.stored_normals;
  int slot_cull = BvhOptions{}.packet_slot_cull;
};

std::string json_array(const std::vector<double>& v) {
  std::string s = "[";
  char buf[32];
  for (std::size_t k = 0; k < v.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%s%.6f", k ? "," : "", v[k]);
    s += buf;
  }
  return s + "]";
}

// BvhBuildTimes' stages, in the order bench rays prints them.
constexpr const char* kBuildStages[] = {"tree", "align", "collapse", "sort", "fill"};
using StageRuns = std::array<std::vector<double>, std::size(kBuildStages)>;

// Each stage's median: a JSON object in seconds, or "ms: tree 12.34, align …" for the text report.
std::string stage_medians(const StageRuns& runs, bool json) {
  std::string s = json ? "{" : "ms: ";
  char buf[64];
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (json) {
      std::snprintf(buf, sizeof buf, "%s\"%s\":%.6f", k ? "," : "", kBuildStages[k], median(runs[k]));
    } else {
      std::snprintf(buf, sizeof buf, "%s%s %.2f", k ? ", " : "", kBuildStages[k], median(runs[k]) * 1e3);
    }
    s += buf;
  }
  return json ? s + "}" : s;
}

void parse_size(const std::string& s, int& w, int& h) {
  const auto x = s.find('x');
  try {
    std::size_t a = 0, b = 0;
    if (x == std::string::npos) throw std::invalid_argument(s);
    w = std::stoi(s.substr(0, x), &a);
    h = std::stoi(s.substr(x + 1), &b);
    if (a != x || b != s.size() - x - 1 || w < 1 || h < 1 || w > 16384 || h > 16384)
      throw std::invalid_argument(s);
  } catch (const std::exception&) {
    throw InputError("--size: expected WxH with 1 <= W, H <= 16384, e.g. 1024x1024, got '" + s + "'");
  }
}

void print_set_json(const char* key, const SetResult& r, bool comma) {
  std::printf("\"%s\":{\"rays\":%llu,\"hits\":%llu,\"checksum\":%llu,\"mrays_per_s\":%.4f}%s", key,
              (unsigned long long)r.rays, (unsigned long long)r.hits, (unsigned long long)r.checksum,
              r.mrays_per_s(), comma ? "," : "");
}

void print_sets_json(const TracerRun& r) {
  print_set_json("primary", r.primary, true);
  print_set_json("primary_packet", r.primary_packet, true);
  print_set_json("shadow", r.shadow, true);
  print_set_json("shadow_packet", r.shadow_packet, true);
  print_set_json("incoherent", r.incoherent, false);
}

void print_row(const char* name, const SetResult& r, const SetResult* rival, uint64_t mismatches) {
  std::printf("%-15s %10llu %10llu %22llu %9.2f", name, (unsigned long long)r.rays,
              (unsigned long long)r.hits, (unsigned long long)r.checksum, r.mrays_per_s());
  if (rival)
    std::printf(" %9.2f %7.2fx %10llu", rival->mrays_per_s(),
                rival->mrays_per_s() > 0 ? r.mrays_per_s() / rival->mrays_per_s() : 0.0,
                (unsigned long long)mismatches);
  std::printf("\n");
}

// Vector FMAs per cycle at each vector width this CPU has (0 where it has none): the numbers that
// tell a host running 512-bit operations at half rate (about 1 at avx512, 2 at avx2: the same 16
// lanes a cycle, so a 16-wide kernel keeps no edge over an 8-wide one) from one whose vector pipes
// are shared (both low). Printed with every run so that ratios quoted from it carry their host.
struct FmaRates {
  double avx2 = 0, avx512 = 0;
};
FmaRates measure_fma_rates() {
  const double ghz = measure_clock_ghz();
  FmaRates r;
  if (ghz > 0) {
    r.avx2 = measure_fma_per_ns(Isa::avx2) / ghz;
    r.avx512 = measure_fma_per_ns(Isa::avx512) / ghz;
  }
  return r;
}

int run(const Options& o) {
  int width = 0, height = 0;
  parse_size(o.size, width, height);
  if (o.repeats < 1) throw InputError("--repeats: must be at least 1");
  if (o.builds < 1 || o.builds > 100) throw InputError("--builds: must be 1 to 100");
  if (o.vs_embree && !embree_available()) {
    // a build without Embree is the build's choice; a build with it whose module is missing is broken
    if (embree_built()) throw RuntimeError("--vs-embree: " + embree_unavailable_reason());
    throw InputError("--vs-embree: " + embree_unavailable_reason());
  }
  const TraceConfig config = resolve_trace_options(o.trace);
  const int threads = omp_get_max_threads();
  if (o.width != 0) {
    const BvhWidths w = bvh_widths(config.isa);
    std::string allowed;
    bool ok = false;
    for (int k = 0; k < w.count; ++k) {
      ok = ok || w.widths[k] == o.width;
      allowed += (k ? ", " : "") + std::to_string(w.widths[k]);
    }
    if (!ok)
      throw InputError("--bvh-width: " + std::string(isa_name(config.isa)) + " traverses nodes of " +
                       allowed + " children (or 0 for the default)");
  }
  const StageLine stages("bench rays");
  const Progress progress = stages.progress();
  progress("loading " + o.model);
  const ObjModel model = load_obj(o.model, ObjLoadOptions{.available_threads = threads});
  const TriangleMesh& mesh = model.mesh;

  BvhOptions bvh_options;
  bvh_options.width = o.width;
  if (o.max_leaf != 0) {
    if (o.max_leaf < 1 || o.max_leaf > int(kMaxLeafTriangles))
      throw InputError("--max-leaf: must be 1 to " + std::to_string(kMaxLeafTriangles));
    bvh_options.sah.max_leaf = uint32_t(o.max_leaf);
    bvh_options.leaves_from_kernel = false;
  }
  if (o.leaf_call < -1 || o.leaf_call > 2) throw InputError("--direct-leaf: must be -1, 0, 1 or 2");
  bvh_options.leaf_call = o.leaf_call;
  if (o.merge_steps < 0 || o.merge_steps > int(kMaxLeafTriangles))
    throw InputError("--merge-steps: must be 0 to " + std::to_string(kMaxLeafTriangles));
  bvh_options.merge_steps = o.merge_steps;
  if (!(o.split_budget >= 0 && o.split_budget <= 1)) throw InputError("--split-budget: must be 0 to 1");
  bvh_options.sah.split_budget = float(o.split_budget);
  if (o.stored_normals < -1 || o.stored_normals > 1) throw InputError("--stored-normals: must be -1, 0 or 1");
  bvh_options.stored_normals = o.stored_normals;
  if (o.slot_cull < -1 || o.slot_cull > 1) throw InputError("--slot-cull: must be -1, 0 or 1");
  bvh_options.packet_slot_cull = o.slot_cull;
  if (o.leaf_block != 0) {
    if (o.leaf_block < 1 || o.leaf_block > 32) throw InputError("--leaf-block: must be 1 to 32");
    bvh_options.sah.leaf_block = uint32_t(o.leaf_block);
    bvh_options.leaves_from_kernel = false;
  }
  if (o.leaf_steps < 0 || o.leaf_steps > 2) throw InputError("--leaf-steps: must be 0, 1 or 2");
  if (o.leaf_steps != 0 && !bvh_options.leaves_from_kernel)
    throw InputError("--leaf-steps: not with --max-leaf or --leaf-block, which size the leaves themselves");
  bvh_options.leaf_steps = o.leaf_steps;
  // start the OpenMP threads before timing (Embree's device starts its threads before its build too)
#pragma omp parallel
  { (void)omp_get_thread_num(); }
  // `builds` builds of each, rayvec's first, then Embree's: interleaved, each build's threads would
  // compete with the other library's still-spinning workers (measured: rayvec's 1.3 ms builds of a
  // 4k mesh took 1.8 ms, some 10 ms). The previous structure is freed before the next build; the
  // last one is traced.
  std::unique_ptr<BvhAccelerator> bvh;
  std::unique_ptr<RayTracer> embree;
  // the rival gets the same ISA: Embree's widest at most rayvec's (it has no scalar code: SSE2)
  const char* embree_isa = config.isa == Isa::avx512 ? "avx512" : (config.isa == Isa::avx2 ? "avx2" : "sse2");
  std::vector<double> build_runs, embree_build_runs;
  StageRuns stage_runs;
  for (int b = 0; b < o.builds; ++b) {
    progress("building the BVH (" + std::to_string(b + 1) + " of " + std::to_string(o.builds) + ")");
    bvh.reset();
    const auto t0 = std::chrono::steady_clock::now();
    bvh = std::make_unique<BvhAccelerator>(mesh, config, bvh_options);
    build_runs.push_back(seconds_since(t0));
    const BvhBuildTimes& t = bvh->build_times();
    const double stages[] = {t.tree, t.align, t.collapse, t.sort, t.fill};  // kBuildStages' order
    for (std::size_t k = 0; k < stage_runs.size(); ++k) stage_runs[k].push_back(stages[k]);
  }
  for (int b = 0; o.vs_embree && b < o.builds; ++b) {
    progress("building Embree's BVH (" + std::to_string(b + 1) + " of " + std::to_string(o.builds) + ")");
    embree.reset();
    double s = 0;
    embree = make_embree_tracer(mesh, threads, embree_isa, s);
    embree_build_runs.push_back(s);
  }
  const double build_s = median(build_runs);
  const double embree_build_s = o.vs_embree ? median(embree_build_runs) : 0.0;
  const double tris = double(mesh.size() ? mesh.size() : 1);
  const double bytes_per_tri = double(bvh->bytes()) / tris;

  const auto ours = make_accelerator_tracer(*bvh);
  progress("making the rays");
  const BenchRays rays = make_bench_rays(mesh, width, height, *ours);
  std::vector<const RayTracer*> tracers{ours.get()};
  if (embree) tracers.push_back(embree.get());
  const std::vector<TracerRun> runs = run_bench_rays(tracers, rays, o.repeats, progress);
  stages.clear();
  const TracerRun& run = runs[0];
  const TracerRun rival_run = embree ? runs[1] : TracerRun{};
  const Mismatches mismatches = embree ? count_mismatches(run, rival_run) : Mismatches{};
  const FmaRates fma = measure_fma_rates();

  // triangle references in the leaves (padding slots aside): above 1 a triangle with spatial splits
  std::size_t references = 0;
  for (std::size_t slot = 0; slot < bvh->triangles().size(); ++slot)
    references += bvh->triangles().id(slot) >= 0 ? 1 : 0;
  const double refs_per_tri = mesh.size() ? double(references) / double(mesh.size()) : 0.0;
  const float split_budget = bvh_options.sah.split_budget;
  if (o.json) {
    std::printf(
        "{\"model\":%s,\"triangles\":%zu,\"width\":%d,\"height\":%d,\"cpu\":%s,\"isa\":%s,"
        "\"intersector\":%s,\"threads\":%d,\"clock\":%s,\"bvh_width\":%d,\"direct_leaf\":%s,"
        "\"leaf_call\":\"%s\",\"leaf_block\":%u,\"leaf_steps\":%d,\"merge_steps\":%d,\"split_budget\":%.3f,"
        "\"references_per_tri\":%.4f,\"stored_normals\":%s,\"packet_slot_cull\":%s,"
        "\"builds\":%d,\"build_s\":%.6f,\"build_runs_s\":%s,\"build_stages_s\":%s,"
        "\"bytes_per_tri\":%.3f,\"fma_per_cycle\":{\"avx2\":%.2f,\"avx512\":%.2f},",
        json_string(o.model).c_str(), mesh.size(), width, height, json_string(cpu_features().brand).c_str(),
        json_string(isa_name(config.isa)).c_str(), json_string(intersector_name(config.intersector)).c_str(),
        threads, bench_uses_thread_cpu_time() ? "\"thread_cpu\"" : "\"wall\"", bvh->tree().width(),
        bvh->traversal().leaf_call != LeafCall::table ? "true" : "false",
        leaf_call_name(bvh->traversal().leaf_call), bvh->leaf_block(), bvh->leaf_steps(), o.merge_steps,
        double(split_budget), refs_per_tri, bvh->triangles().stores_normals() ? "true" : "false",
        bvh->tree().arrays().packet_slot_cull ? "true" : "false", o.builds, build_s,
        json_array(build_runs).c_str(), stage_medians(stage_runs, true).c_str(), bytes_per_tri, fma.avx2,
        fma.avx512);
    print_sets_json(run);
    if (o.vs_embree) {
      std::printf(",\"embree\":{\"build_s\":%.6f,\"build_runs_s\":%s,\"max_isa\":\"%s\",", embree_build_s,
                  json_array(embree_build_runs).c_str(), embree_isa);
      print_sets_json(rival_run);
      std::printf(
          ",\"mismatches\":{\"primary\":%llu,\"primary_packet\":%llu,\"shadow\":%llu,"
          "\"shadow_packet\":%llu,\"incoherent\":%llu}}",
          (unsigned long long)mismatches.primary, (unsigned long long)mismatches.primary_packet,
          (unsigned long long)mismatches.shadow, (unsigned long long)mismatches.shadow_packet,
          (unsigned long long)mismatches.incoherent);
    }
    std::printf("}\n");
    return 0;
  }
  std::printf(
      "model: %s, %zu triangles; %dx%d; median of %d runs after a warm-up%s (%s clock; "
      "builds: wall clock, median of %d%s)\n",
      o.model.c_str(), mesh.size(), width, height, o.repeats, embree ? ", interleaved with embree's" : "",
      bench_uses_thread_cpu_time() ? "thread CPU-time" : "wall", o.builds,
      embree ? " each, rayvec's then embree's" : "");
  std::printf("cpu: %s; isa: %s; intersector: %s; threads: %d\n", cpu_features().brand.c_str(),
              isa_name(config.isa), intersector_name(config.intersector), threads);
  std::printf("vector FMAs per cycle: avx2 %.2f, avx512 %.2f%s\n", fma.avx2, fma.avx512,
              fma.avx512 > 0 && fma.avx512 < 0.7 * fma.avx2
                  ? " (512-bit operations at half rate here: 16-wide kernels keep no edge in lanes a cycle)"
                  : "");
  const std::string leaf_steps_text = bvh->leaf_steps() > 0
                                          ? std::to_string(bvh->leaf_steps()) + "-step leaves"
                                          : "leaves up to the builder's size";
  std::printf(
      "bvh: %d-wide, %u nodes, %u leaves (SAH leaf block %u, %s, merged up to %d kernel steps), "
      "%.3f references per triangle (spatial-split budget %.2f), depth %u, leaf kernel: %s, normals %s, "
      "packet slot cull %s; "
      "build %.4f s (%s); %.1f bytes/triangle (nodes %.1f + triangles %.1f)\n",
      bvh->tree().width(), bvh->tree().node_count(), bvh->tree().leaf_count(), bvh->leaf_block(),
      leaf_steps_text.c_str(), o.merge_steps, refs_per_tri, double(split_budget), bvh->tree().depth(),
      leaf_call_name(bvh->traversal().leaf_call),
      bvh->triangles().stores_normals() ? "stored" : "formed per step",
      bvh->tree().arrays().packet_slot_cull ? "on" : "off", build_s, stage_medians(stage_runs, false).c_str(),
      bytes_per_tri, double(bvh->tree().bytes()) / tris, double(bvh->triangles().bytes()) / tris);
  if (o.vs_embree)
    std::printf(
        "embree: max_isa=%s, RTC_BUILD_QUALITY_HIGH build %.4f s (rayvec/embree build time "
        "%.2f)\n",
        embree_isa, embree_build_s, embree_build_s > 0 ? build_s / embree_build_s : 0.0);
  std::printf("%-15s %10s %10s %22s %9s", "set", "rays", "hits", "checksum", "Mrays/s");
  if (o.vs_embree) std::printf(" %9s %8s %10s", "embree", "ratio", "mismatches");
  std::printf("\n");
  const bool e = o.vs_embree;
  print_row("primary", run.primary, e ? &rival_run.primary : nullptr, mismatches.primary);
  print_row("primary_packet", run.primary_packet, e ? &rival_run.primary_packet : nullptr,
            mismatches.primary_packet);
  print_row("shadow", run.shadow, e ? &rival_run.shadow : nullptr, mismatches.shadow);
  print_row("shadow_packet", run.shadow_packet, e ? &rival_run.shadow_packet : nullptr,
            mismatches.shadow_packet);
  print_row("incoherent", run.incoherent, e ? &rival_run.incoherent : nullptr, mismatches.incoherent);
  if (e)
    std::printf(
        "ratio = rayvec Mrays/s / embree Mrays/s (rtcIntersect1, rtcIntersect16 per 4x4 "
        "tile, rtcOccluded1, rtcOccluded16 per tile, rtcIntersect1); mismatches = rays whose triangle id "
        "(shadow: "
        "occlusion) differs\n");
  return 0;
}

}  // namespace

void register_bench_rays_command(Command& bench) {
  static Options o;
  Command& cmd = bench.subcommand("rays",
                                  "BVH build time and Mrays/s of primary, packet, shadow "
                                  "and incoherent rays on one OBJ mesh (optionally vs Embree)");
  cmd.positional("MODEL", o.model, "Wavefront OBJ mesh")
      .option("--size", o.size, "image size WxH of the primary rays (default 1024x1024)")
      .flag("--json", o.json, "print one JSON object instead of the table")
      .flag("--vs-embree", o.vs_embree,
            "also trace the same rays with Embree 3 (RTC_BUILD_QUALITY_HIGH, its ISA capped at "
            "rayvec's: --isa avx2 compares AVX2 with AVX2) and print ratios and id mismatches; "
            "exit status 2 when rayvec was built without Embree")
      .option("--repeats", o.repeats,
              "timed runs per ray set after one warm-up; the median is "
              "reported (default 5)")
      .option("--builds", o.builds,
              "BVH builds timed (with --vs-embree: as many of Embree's after them); the median "
              "is reported, the last tree is traced (default 3)")
      .option("--bvh-width", o.width,
              "children per BVH node: 8 or 16 (the scalar ISA also 4); 0 = the default (AVX-512 and "
              "AVX2: 16 from 32768 triangles up, else 8; AVX-512 on Intel: 16 at every size)")
      .option("--leaf-steps", o.leaf_steps,
              "tuning: most leaf-kernel steps (16 triangles on AVX-512, 8 on AVX2) a SAH leaf holds, 1 or 2; "
              "0 = the default (1 below " +
                  std::to_string(kWideNodeTriangles) + " triangles, 2 from there)")
      .option("--max-leaf", o.max_leaf, "tuning: most triangles per BVH leaf (0 = default)")
      .option("--leaf-block", o.leaf_block, "tuning: SAH leaf cost = ceil(n / leaf-block) (0 = default)")
      .option("--merge-steps", o.merge_steps,
              "tuning: a subtree whose triangles fit in this many leaf-kernel steps (at most 32 "
              "slots) becomes one leaf instead of a node of its own; 0 = never (default 3)")
      .option("--split-budget", o.split_budget,
              "tuning: spatial splits may add up to this fraction of the triangles as extra leaf "
              "references (0 = none; default 0.3)")
      .option("--stored-normals", o.stored_normals,
              "tuning: the triangle rows store the mt kernels' normals (1) or the kernels form them per "
              "step (0); -1 = default (stored below " +
                  std::to_string(kFormedNormalsFrom) + " triangles while the BVH stays within " +
                  std::to_string(int(kBvhBytesPerTriangle)) + " bytes a triangle)")
      .option("--direct-leaf", o.leaf_call,
              "tuning: how the traversals reach the mt or watertight leaf kernel: through the kernel "
              "table (0), called directly (1), called directly with the closest-hit kernel inlined into "
              "the traversal (2); -1 = default (directly on AVX2 and AVX-512, inlined from " +
                  std::to_string(kWideNodeTriangles) + " triangles up)")
      .option("--slot-cull", o.slot_cull,
              "tuning: packets step only the leaf triangles whose boxes their hull reaches (1) or every "
              "triangle (0); -1 = default (below " +
                  std::to_string(kPacketSlotCullBelow) + " triangles)");
  add_trace_options(cmd, o.trace, false);
  cmd.footer(
      "Ray sets (exact definitions in src/bench/ray_sets.h): primary = a pinhole camera framing the\n"
      "mesh (single rays, and 4x4 tiles through Accelerator::closest_stream); shadow = any-hit from\n"
      "each primary hit toward a light above the eye (single rays, and the rays of each 4x4 tile's\n"
      "hits through Accelerator::occluded_stream); incoherent = closest hit from each primary\n"
      "hit in a random direction on the normal's hemisphere. checksum = sum over hits of\n"
      "(pixel+1)*(triangle id+1) mod 2^64 (shadow: sum of pixel+1 over occluded rays).\n"
      "Example: rayvec bench rays bumpy_sphere.obj --size 512x512 --threads 1 --vs-embree");
  cmd.run([] { return run(o); });
}

}  // namespace rayvec
