// `rayvec hits`: trace the rays of a CSV file against an OBJ mesh; one closest hit (or any-hit flag)
// per ray, as CSV.
#include <omp.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <vector>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/device_option.h"
#include "app/trace_options.h"
#include "distributed/rays_across_ranks.h"
#include "io/error_report.h"
#include "io/hits_csv.h"
#include "io/input_error.h"
#include "io/output_sink.h"
#include "io/rays_csv.h"
#include "platform/stopwatch.h"
#include "scene/obj_loader.h"

namespace rayvec {
namespace {

struct HitsArgs {
  std::string mesh, rays, output;
  bool any = false;
  TraceOptions trace;
  DeviceOptions device;
};

int run_hits(const HitsArgs& args) {
  const TraceConfig config = resolve_trace_options(args.trace);
  const AccelKind kind = resolve_accel(args.trace);
  const bool cuda = resolve_device(args.device, config.intersector);
  const ObjModel model = load_obj(args.mesh, ObjLoadOptions{.available_threads = omp_get_max_threads()});
  report_warnings(model.warnings);
  // Under mpirun rank 0 reads the rays and writes the answers (its share of the rays goes to each rank).
  const bool root = cluster().root();
  if (cuda && cluster().distributed())
    throw InputError("--device cuda runs in one process: launch it without mpirun, or use --device cpu");
  const RayBatch rays = root ? read_rays_csv(args.rays) : RayBatch{};
  if (cuda) require_cuda_device();
  OutputSink out(root ? args.output : "");  // opened before tracing: an unwritable path fails fast

  const auto accel = cuda ? nullptr : make_accelerator(kind, model.mesh, config);
  const auto tracer = cuda ? cuda_tracer(model.mesh) : nullptr;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();  // CPU time too: wall time inflates on a shared machine
  std::size_t hit_count = 0;
  std::vector<Hit> hits;
  std::vector<uint8_t> occluded;
  RankLoads loads;
  if (args.any) {
    if (cuda)
      occluded = cuda_occluded(*tracer, rays, config.intersector, args.device);
    else
      trace_occluded_across_ranks(cluster(), *accel, rays, occluded, loads);
    for (uint8_t o : occluded) hit_count += o;
  } else {
    if (cuda)
      hits = cuda_closest(*tracer, rays, config.intersector, args.device);
    else
      trace_closest_across_ranks(cluster(), *accel, rays, hits, loads);
    for (const Hit& h : hits) hit_count += h.hit();
  }
  if (!root) return 0;
  const double seconds = seconds_since(start);
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;

  if (args.any)
    write_any_hits_csv(out, occluded);
  else
    write_hits_csv(out, hits);
  out.commit();
  std::fprintf(stderr,
               "hits: %zu rays, %zu triangles, %zu %s, %.3f s (%.3f s cpu), %.2f Mrays/s (%s, isa %s, "
               "intersector %s, %d threads)\n",
               rays.size(), model.mesh.size(), hit_count, args.any ? "occluded" : "hits", seconds,
               cpu_seconds, seconds > 0 ? rays.size() / seconds * 1e-6 : 0.0,
               cuda ? device_summary(*tracer, args.device).c_str() : accel_name(kind), isa_name(config.isa),
               intersector_name(config.intersector), omp_get_max_threads());
  if (cluster().distributed()) std::fprintf(stderr, "hits: %s", loads.text().c_str());
  return 0;
}

const char* const kHitsFooter = R"(Input:
  MODEL.obj  Wavefront OBJ (+ MTL); polygons are triangulated as tinyobjloader does, and the
             triangle id is the 0-based index of the triangle in file order after that.
  RAYS.csv   one ray per line: ox,oy,oz,dx,dy,dz  or  ox,oy,oz,dx,dy,dz,tmin,tmax
             (defaults tmin = 0, tmax = inf; '#' lines and blank lines are skipped).
             A ray is o + t*d for tmin <= t <= tmax; d need not be normalized.
Output (stdout, or -o FILE written atomically):
  ray,tri,t,u,v   one line per ray in input order; a miss is tri -1, t inf, u v 0.
  ray,hit         with --any: 1 when some triangle is hit within [tmin, tmax], else 0.
  Floats are printed so that they read back to the same float.
A one-line summary (rays, hits, tracing seconds on the wall clock and of CPU, Mrays/s, isa,
intersector, threads) goes to stderr.
With --device cuda the rays are traced brute force on the GPU (docs/gpu.md): the same hits as the
CPU's AVX2/AVX-512 kernels; no CUDA device is a runtime failure (exit 1, nothing written).
Exit status: 0 done, 2 bad input or usage (message `file:line: what is wrong`), 1 runtime failure
(e.g. the output cannot be written). See docs/formats.md.

Example:
  printf 'v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n' > tri.obj
  printf 'ox,oy,oz,dx,dy,dz\n0,0,-1,0,0,1\n5,5,-1,0,0,1\n' > rays.csv
  rayvec hits --mesh tri.obj --rays rays.csv
    ray,tri,t,u,v
    0,0,1,0.25,0.5
    1,-1,inf,0,0)";

}  // namespace

void register_hits_command(CommandLine& cli) {
  static HitsArgs args;
  Command& cmd =
      cli.command("hits", "Trace the rays of a CSV file against an OBJ mesh; print the hits as CSV");
  cmd.required("--mesh", args.mesh, "the triangle mesh (Wavefront OBJ)")
      .required("--rays", args.rays, "the rays (CSV: ox,oy,oz,dx,dy,dz[,tmin,tmax]; - reads standard input)")
      .flag("--any", args.any, "any-hit (occlusion) query: print ray,hit with 0/1")
      .option("-o,--output", args.output, "output CSV file (default: standard output)");
  add_trace_options(cmd, args.trace, true);
  add_device_options(cmd, args.device);
  cmd.footer(kHitsFooter).run([] { return run_hits(args); });
}

}  // namespace rayvec
