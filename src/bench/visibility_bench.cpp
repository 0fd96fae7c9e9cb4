#include "bench/visibility_bench.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "accel/accelerator.h"
#include "accel/visibility.h"
#include "bench/median.h"
#include "gpu/cuda_backend.h"
#include "gpu/visibility_segments.h"
#include "platform/isa.h"
#include "platform/stopwatch.h"

namespace rayvec {
namespace {

constexpr float kPi = 3.14159265358979f;
const Vec3f kOrigin{0.0f, 0.0f, -3.0f};  // as docs/benchmarks.md's visibility command

struct Workload {
  TriangleMesh mesh;
  std::vector<Vec3f> verts;
  std::vector<Visibility> reference;
  double tests = 0;  // vertices × triangles: one brute-force pass
};

struct Printer {
  std::FILE* out;
  const Workload* w;
  const std::vector<Visibility>* reference;
  int failures = 0;

  std::string check(const std::vector<Visibility>& got) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < got.size(); ++i) differ += got[i] != (*reference)[i];
    if (differ == 0) return "ok";
    ++failures;
    return "MISMATCH: " + std::to_string(differ) + " vertices";
  }
  void row(const std::string& name, const std::string& threads, double seconds, const std::string& transfer,
           const std::string& check) {
    std::fprintf(out, "| %s | %s | %.4f | %s | %.0f | %s |\n", name.c_str(), threads.c_str(), seconds,
                 transfer.c_str(), w->tests / seconds * 1e-6, check.c_str());
  }
  void absent(const std::string& name, const std::string& why) {
    std::fprintf(out, "| %s | — | — | — | — | absent: %s |\n", name.c_str(), why.c_str());
  }
};

std::vector<int> thread_counts(int max_threads) {
  std::vector<int> out;
  for (int t = 1; t < max_threads; t *= 2) out.push_back(t);
  out.push_back(max_threads);
  return out;
}

void cpu_rows(const VisibilityBenchOptions& o, const Workload& w, int max_threads, Printer& p) {
  TraceConfig config;
  config.intersector = o.intersector;
  for (Isa isa : supported_isas()) {
    config.isa = isa;
    const auto brute = make_accelerator(AccelKind::brute, w.mesh, config);
    for (int threads : thread_counts(max_threads)) {
      const std::string name = std::string("CPU brute force, ") + isa_name(isa) +
                               (isa == Isa::scalar && threads == 1 ? " (the study's sequential row)" : "");
      if (w.tests / threads > o.cpu_budget) {
        char why[160];
        std::snprintf(why, sizeof why, "%.2g tests per thread at %d threads exceed --cpu-budget %.2g",
                      w.tests / threads, threads, o.cpu_budget);
        p.absent(name + " (" + std::to_string(threads) + " threads)", why);
        continue;
      }
      omp_set_num_threads(threads);
      const auto start = std::chrono::steady_clock::now();
      const auto got = compute_visibility(*brute, w.mesh, w.verts, kOrigin);
      p.row(name, std::to_string(threads), seconds_since(start), "—", p.check(got));
    }
  }
  config.isa = best_isa();
  omp_set_num_threads(max_threads);
  const auto bvh = make_accelerator(AccelKind::bvh, w.mesh, config);
  const auto start = std::chrono::steady_clock::now();
  const auto got = compute_visibility(*bvh, w.mesh, w.verts, kOrigin);
  p.row(std::string("CPU BVH, ") + isa_name(config.isa) + " (build not timed)", std::to_string(max_threads),
        seconds_since(start), "—", p.check(got));
}

void gpu_rows(const VisibilityBenchOptions& o, const Workload& w, Printer& p) {
  if (!gpu::cuda_built()) return p.absent("GPU (all kernels)", "built without CUDA (-DRAYVEC_CUDA=ON)");
  const gpu::CudaSystem sys = gpu::cuda_system();
  if (sys.devices.empty()) return p.absent("GPU (all kernels)", "no CUDA device found (" + sys.error + ")");
  try {
    gpu::CudaTracer tracer(gpu::make_gpu_triangles(w.mesh));
    const gpu::VisibilitySegments s = gpu::visibility_segments(w.verts, kOrigin);
    std::vector<gpu::GpuLaunch> launches{{gpu::GpuKernel::global, 256}};
    for (gpu::GpuKernel k : {gpu::GpuKernel::shared, gpu::GpuKernel::soa})
      for (int tile : o.tiles) launches.push_back({k, tile});
    for (const gpu::GpuLaunch& l : launches) {
      // one warm-up, then the median kernel time of 3 runs; the transfers of the last run
      std::vector<double> kernel;
      gpu::GpuTimes t;
      std::vector<uint8_t> occluded;
      for (int r = 0; r < 4; ++r) {
        occluded = tracer.occluded(s.rays, s.points.data(), o.intersector, l, &t);
        if (r > 0) kernel.push_back(t.kernel_s);
      }
      char transfer[96];
      std::snprintf(transfer, sizeof transfer, "%.4f up + %.4f down (+ %.4f triangles once)", t.upload_s,
                    t.download_s, tracer.upload_seconds());
      std::string name = "GPU " + std::string(gpu::gpu_kernel_name(l.kernel)) + ", " + tracer.device_name();
      if (l.kernel != gpu::GpuKernel::global) name += ", tile " + std::to_string(l.tile);
      p.row(name, "—", median(kernel), transfer,
            p.check(gpu::visibility_answers(s, w.verts.size(), occluded)));
    }
  } catch (const gpu::CudaError& e) {
    ++p.failures;
    p.absent("GPU", std::string("failed: ") + e.what());
  }
}

}  // namespace

TriangleMesh bumpy_sphere(int rings) {
  const int segments = 2 * rings;
  TriangleMesh m;
  auto radius = [](float theta, float phi) { return 1.0f + 0.08f * std::sin(7 * theta) * std::sin(5 * phi); };
  m.positions.push_back({0, 0, -1});  // the pole facing the origin
  for (int r = 1; r < rings; ++r) {
    const float theta = kPi * float(r) / float(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2 * kPi * float(s) / float(segments);
      const float rad = radius(theta, phi);
      m.positions.push_back({rad * std::sin(theta) * std::cos(phi), rad * std::sin(theta) * std::sin(phi),
                             -rad * std::cos(theta)});
    }
  }
  m.positions.push_back({0, 0, 1});
  const auto ring = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
  const uint32_t last = uint32_t(m.positions.size() - 1);
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({0, ring(1, s + 1), ring(1, s)});
    for (int r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s)});
      m.triangles.push_back({ring(r, s + 1), ring(r + 1, s + 1), ring(r + 1, s)});
    }
    m.triangles.push_back({last, ring(rings - 1, s), ring(rings - 1, s + 1)});
  }
  return m;
}

int run_visibility_bench(const VisibilityBenchOptions& o, std::FILE* out) {
  const int max_threads = o.max_threads > 0 ? o.max_threads : omp_get_num_procs();
  int failures = 0;
  for (int rings : o.rings) {
    Workload w;
    w.mesh = bumpy_sphere(rings);
    w.verts = w.mesh.positions;
    w.tests = double(w.verts.size()) * double(w.mesh.size());
    TraceConfig config;
    config.isa = best_isa();
    config.intersector = o.intersector;
    omp_set_num_threads(max_threads);
    w.reference =
        compute_visibility(*make_accelerator(AccelKind::bvh, w.mesh, config), w.mesh, w.verts, kOrigin);
    std::size_t visible = 0;
    for (Visibility v : w.reference) visible += v == Visibility::visible;
    std::fprintf(out,
                 "\n### %zu vertices × %zu triangles (rings %d; %zu visible from 0,0,-3), intersector %s\n\n"
                 "| row | threads | seconds | transfer seconds | Mtests/s | check vs BVH |\n"
                 "|---|---|---|---|---|---|\n",
                 w.verts.size(), w.mesh.size(), rings, visible, intersector_name(o.intersector));
    Printer p{out, &w, &w.reference};
    cpu_rows(o, w, max_threads, p);
    if (o.gpu) gpu_rows(o, w, p);
    std::fflush(out);
    failures += p.failures;
  }
  omp_set_num_threads(max_threads);
  return failures;
}

}  // namespace rayvec
