#include "app/device_option.h"

#include <cstdio>

#include "app/command_line.h"
#include "gpu/math_dispatch.h"
#include "gpu/visibility_segments.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

std::vector<Ray> to_rays(const RayBatch& batch) {
  std::vector<Ray> rays(batch.size());
  for (std::size_t i = 0; i < rays.size(); ++i) rays[i] = batch[i];
  return rays;
}

// Device failures (out of memory, a failed launch) are runtime failures: exit 1.
template <class F>
auto on_device(F&& f) {
  try {
    return f();
  } catch (const gpu::CudaError& e) {
    throw RuntimeError(e.what());
  }
}

}  // namespace

void add_device_options(Command& cmd, DeviceOptions& options) {
  cmd.option("--device", options.device,
             "cpu (default) or cuda: brute force on the first NVIDIA GPU (--accel applies to the CPU only; "
             "see docs/gpu.md)")
      .option("--gpu-kernel", options.kernel,
              "with --device cuda: global (triangles read from global memory), shared (tiles of triangle "
              "records in shared memory) or soa (tiles loaded from SoA rows; default)")
      .option("--tile", options.tile, "with --device cuda: triangles per shared-memory tile, 64 to 1024");
}

bool resolve_device(const DeviceOptions& options, Intersector intersector) {
  if (options.device != "cpu" && options.device != "cuda")
    throw InputError("--device: unknown '" + options.device + "' (choose cpu or cuda)");
  if (!gpu::parse_gpu_kernel(options.kernel))
    throw InputError("--gpu-kernel: unknown '" + options.kernel + "' (choose global, shared or soa)");
  if (options.tile < gpu::kMinTile || options.tile > gpu::kMaxTile)
    throw InputError("--tile: must be between 64 and 1024 triangles, got " + std::to_string(options.tile));
  if (options.device == "cpu") return false;
  if (!gpu::cuda_built())
    throw InputError(
        "--device cuda: this rayvec was built without CUDA (configure with -DRAYVEC_CUDA=ON and nvcc "
        "installed; see docs/gpu.md), or use --device cpu");
  if (!gpu::device_supports(intersector))
    throw InputError(std::string("--device cuda: intersector ") + intersector_name(intersector) +
                     " is CPU-only (choose mt, mt64, watertight or watertight64)");
  return true;
}

void require_cuda_device() {
  const gpu::CudaSystem s = gpu::cuda_system();
  if (s.devices.empty())
    throw RuntimeError("--device cuda: no CUDA device found (" + s.error + "); use --device cpu");
}

std::unique_ptr<gpu::CudaTracer> cuda_tracer(const TriangleMesh& mesh) {
  return on_device([&] { return std::make_unique<gpu::CudaTracer>(gpu::make_gpu_triangles(mesh)); });
}

gpu::GpuLaunch device_launch(const DeviceOptions& options) {
  return gpu::GpuLaunch{*gpu::parse_gpu_kernel(options.kernel), options.tile};
}

std::vector<Visibility> cuda_visibility(gpu::CudaTracer& tracer, const std::vector<Vec3f>& verts,
                                        Vec3f origin, Intersector intersector, const DeviceOptions& options) {
  const gpu::VisibilitySegments s = gpu::visibility_segments(verts, origin);
  const std::vector<uint8_t> occluded = on_device(
      [&] { return tracer.occluded(s.rays, s.points.data(), intersector, device_launch(options)); });
  return gpu::visibility_answers(s, verts.size(), occluded);
}

std::string device_summary(const gpu::CudaTracer& tracer, const DeviceOptions& options) {
  std::string s = "cuda: " + tracer.device_name() + ", kernel " + options.kernel;
  if (options.kernel != "global") s += ", tile " + std::to_string(options.tile);
  return s;
}

std::vector<uint8_t> cuda_occluded(gpu::CudaTracer& tracer, const RayBatch& rays, Intersector intersector,
                                   const DeviceOptions& options) {
  const std::vector<Ray> r = to_rays(rays);
  return on_device([&] { return tracer.occluded(r, nullptr, intersector, device_launch(options)); });
}

std::vector<Hit> cuda_closest(gpu::CudaTracer& tracer, const RayBatch& rays, Intersector intersector,
                              const DeviceOptions& options) {
  const std::vector<Ray> r = to_rays(rays);
  return on_device([&] { return tracer.closest(r, intersector, device_launch(options)); });
}

void print_cuda_info() {
  if (!gpu::cuda_built()) {
    std::printf("cuda: not built (configure with -DRAYVEC_CUDA=ON; docs/gpu.md)\n");
    return;
  }
  std::printf("cuda: built with CUDA %s for %s\n", gpu::cuda_toolkit_version(), gpu::cuda_architectures());
  const gpu::CudaSystem s = gpu::cuda_system();
  std::printf("cuda runtime: %d.%d, driver: ", s.runtime_version / 1000, s.runtime_version % 1000 / 10);
  if (s.driver_version)
    std::printf("%d.%d\n", s.driver_version / 1000, s.driver_version % 1000 / 10);
  else
    std::printf("none\n");
  if (s.devices.empty()) std::printf("cuda devices: none (%s)\n", s.error.c_str());
  for (std::size_t d = 0; d < s.devices.size(); ++d) {
    const gpu::CudaDeviceInfo& i = s.devices[d];
    std::printf("cuda device %zu: %s, compute capability %d.%d, %d SMs, %.1f GiB\n", d, i.name.c_str(),
                i.major, i.minor, i.multiprocessors, double(i.memory_bytes) / (1024.0 * 1024.0 * 1024.0));
  }
}

}  // namespace rayvec
