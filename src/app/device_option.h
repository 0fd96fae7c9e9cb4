// --device cpu|cuda and its launch options (--gpu-kernel, --tile), shared by `visibility` and
// `hits`: the validation, the device probe and the CUDA runs, so that those commands only branch.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "accel/visibility.h"
#include "gpu/cuda_backend.h"
#include "rays/ray.h"

namespace rayvec {

class Command;

struct DeviceOptions {
  std::string device = "cpu";
  std::string kernel = "soa";
  int tile = 256;
};

void add_device_options(Command& cmd, DeviceOptions& options);

// Validates the values (InputError, exit 2: an unknown device or kernel, a tile outside 64..1024,
// --device cuda in a build without CUDA or with the CPU-only intersector `paper`); true for cuda.
bool resolve_device(const DeviceOptions& options, Intersector intersector);

// RuntimeError (exit 1) "no CUDA device found" unless the runtime lists a device. Call before any
// output is opened, so that nothing is written.
void require_cuda_device();

// The triangles on device 0 (RuntimeError on a device failure).
std::unique_ptr<gpu::CudaTracer> cuda_tracer(const TriangleMesh& mesh);
gpu::GpuLaunch device_launch(const DeviceOptions& options);

// The visibility of every vertex, traced on the device (same answers as compute_visibility).
std::vector<Visibility> cuda_visibility(gpu::CudaTracer& tracer, const std::vector<Vec3f>& verts,
                                        Vec3f origin, Intersector intersector, const DeviceOptions& options);

// "cuda: NAME, kernel K, tile N" for the commands' summary lines.
std::string device_summary(const gpu::CudaTracer& tracer, const DeviceOptions& options);

// Brute force on the device: RuntimeError on a device failure.
std::vector<uint8_t> cuda_occluded(gpu::CudaTracer& tracer, const RayBatch& rays, Intersector intersector,
                                   const DeviceOptions& options);
std::vector<Hit> cuda_closest(gpu::CudaTracer& tracer, const RayBatch& rays, Intersector intersector,
                              const DeviceOptions& options);

// `rayvec info`'s CUDA lines: the build's toolkit and architectures, and the devices the runtime sees
// (initialising it).
void print_cuda_info();

}  // namespace rayvec
