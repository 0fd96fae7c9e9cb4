// `rayvec visibility`: the CUDA study's workload (Gallina 2023) — which vertices of a mesh can be seen
// from an origin — with open segments and a vertex's own triangles ignored (src/accel/visibility.h).
#include <omp.h>

#include <charconv>
#include <cmath>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <string>

#include "accel/visibility.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "app/device_option.h"
#include "app/trace_options.h"
#include "distributed/rays_across_ranks.h"
#include "geometry/coordinate_range.h"
#include "io/input_error.h"
#include "io/output_sink.h"
#include "io/visibility_csv.h"
#include "platform/stopwatch.h"

namespace rayvec {
namespace {

struct VisibilityArgs {
  std::string verts, faces, origin = "0,0,0", output;
  TraceOptions trace;
  DeviceOptions device;
};

// "X,Y,Z" with three finite numbers; InputError (exit 2) otherwise.
Vec3f parse_origin(const std::string& text) {
  float xyz[3];
  std::size_t k = 0, pos = 0;
  for (; k < 3 && pos <= text.size(); ++k) {
    std::size_t comma = text.find(',', pos);
    if (comma == std::string::npos) comma = text.size();
    const char* first = text.data() + pos;
    const char* last = text.data() + comma;
    if (first != last && *first == '+') ++first;
    const auto [end, ec] = std::from_chars(first, last, xyz[k]);
    if (ec != std::errc() || end != last || !std::isfinite(xyz[k])) break;
    pos = comma + 1;
  }
  if (k != 3 || pos != text.size() + 1)
    throw InputError("--origin: '" + text + "' is not X,Y,Z with three finite numbers (e.g. 0,0,-2.5)");
  for (float c : xyz)
    if (!coordinate_in_range(c))
      throw InputError("--origin: '" + text + "' is beyond " + kCoordinateRangeText);
  return {xyz[0], xyz[1], xyz[2]};
}

int run_visibility(const VisibilityArgs& args) {
  const Vec3f origin = parse_origin(args.origin);
  const TraceConfig config = resolve_trace_options(args.trace);
  const AccelKind kind = resolve_accel(args.trace);
  const bool cuda = resolve_device(args.device, config.intersector);
  if (args.verts == "-" && args.faces == "-")
    throw InputError("--verts and --faces cannot both read standard input (give one of them as a file)");
  // Under mpirun rank 0 reads the inputs (standard input reaches it alone) and shares them.
  const bool root = cluster().root();
  if (cuda && cluster().distributed())
    throw InputError("--device cuda runs in one process: launch it without mpirun, or use --device cpu");
  std::vector<Vec3f> verts = root ? read_verts_csv(args.verts) : std::vector<Vec3f>{};
  auto faces = root ? read_faces_csv(args.faces, verts.size()) : std::vector<std::array<uint32_t, 3>>{};
  if (cuda) require_cuda_device();
  OutputSink out(root ? args.output : "");
  cluster().broadcast(verts);
  cluster().broadcast(faces);

  const VisibilityMesh scene = build_visibility_mesh(verts, faces);
  if (scene.dropped)
    std::fprintf(stderr,
                 "warning: %s: %zu of %zu faces dropped: they use a vertex with a non-finite coordinate\n",
                 args.faces.c_str(), scene.dropped, faces.size());
  const auto accel = cuda ? nullptr : make_accelerator(kind, scene.mesh, config);
  const auto tracer = cuda ? cuda_tracer(scene.mesh) : nullptr;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();  // CPU time too: wall time inflates on a shared machine
  RankLoads loads;
  const std::vector<Visibility> result =
      cuda ? cuda_visibility(*tracer, verts, origin, config.intersector, args.device)
           : visibility_across_ranks(cluster(), *accel, scene.mesh, verts, origin, loads);
  if (!root) return 0;
  const double seconds = seconds_since(start);
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;

  std::string text;
  text.reserve(result.size() * 2);
  std::size_t visible = 0, undefined = 0;
  for (Visibility v : result) {
    text += v == Visibility::visible ? "1\n" : v == Visibility::blocked ? "0\n" : "nan\n";
    visible += v == Visibility::visible;
    undefined += v == Visibility::undefined;
  }
  out.write(text.data(), text.size());
  out.commit();
  std::fprintf(
      stderr,
      "visibility: %zu vertices (%zu visible, %zu blocked, %zu nan), %zu triangles, %.3f s (%.3f s cpu) "
      "(%s, isa %s, intersector %s, %d threads)\n",
      result.size(), visible, result.size() - visible - undefined, undefined, scene.mesh.size(), seconds,
      cpu_seconds, cuda ? device_summary(*tracer, args.device).c_str() : accel_name(kind),
      isa_name(config.isa), intersector_name(config.intersector), omp_get_max_threads());
  if (cluster().distributed()) std::fprintf(stderr, "visibility: %s", loads.text().c_str());
  return 0;
}

const char* const kVisibilityFooter = R"(Input (the format of the CUDA visibility study):
  verts.csv   one vertex per row: x,y,z (e.g. -6.195182353258132935e-02,...); rows of nan are kept.
  meshes.csv  one triangle per row: three 0-based vertex row numbers written as floats
              (e.g. 1.000000000000000000e+00,2.000000000000000000e+00,0.000000000000000000e+00).
  Blank lines and lines starting with '#' are skipped (and not counted as rows).
Output (stdout, or -o FILE written atomically): one line per vertex row, in order:
  1    the open segment origin -> vertex crosses no triangle
  0    some triangle crosses it
  nan  the vertex has a non-finite coordinate
Triangles with a corner at the vertex's position never block it. Faces that use a non-finite vertex
are dropped (one warning on stderr). A non-integer, negative or out-of-range index is an error.
With --device cuda the segments are traced brute force on the GPU (docs/gpu.md): the same answers;
no CUDA device is a runtime failure (exit 1, nothing written), a build without CUDA a usage error.
Exit status: 0 done, 2 bad input or usage (`file:line: what is wrong`), 1 runtime failure.
See docs/formats.md.

Example:
  printf '0,0,1\n0,0,2\nnan,nan,nan\n-1,-1,1.5\n1,-1,1.5\n0,1,1.5\n' > verts.csv
  printf '3,4,5\n' > meshes.csv
  rayvec visibility --verts verts.csv --faces meshes.csv
    1
    0
    nan
    1
    1
    1)";

}  // namespace

void register_visibility_command(CommandLine& cli) {
  static VisibilityArgs args;
  Command& cmd =
      cli.command("visibility", "Which vertices are visible from an origin (verts.csv + meshes.csv)");
  cmd.required("--verts", args.verts, "vertex rows x,y,z (CSV; - reads standard input)")
      .required("--faces", args.faces, "triangles as three 0-based vertex rows (CSV; - reads standard input)")
      .option("--origin", args.origin, "the eye point X,Y,Z")
      .option("-o,--output", args.output, "output file (default: standard output)");
  add_trace_options(cmd, args.trace, true);
  add_device_options(cmd, args.device);
  cmd.footer(kVisibilityFooter).run([] { return run_visibility(args); });
}

}  // namespace rayvec
