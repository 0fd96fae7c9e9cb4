// The CUDA backend as the rest of rayvec sees it: plain C++, no CUDA header, the same declarations
// whether or not the build has CUDA (cuda_backend.cu and cuda_info.cu with RAYVEC_CUDA, else
// cuda_absent.cpp). Nothing here runs at start-up: the CUDA runtime initialises on the first call
// that needs it (cuda_system or a CudaTracer), so commands that never ask for a GPU never pay for it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/gpu_scene.h"
#include "kernels/intersector.h"
#include "rays/ray.h"

namespace rayvec::gpu {

// A failure of the device or its runtime (no device, out of memory, a failed launch): exit 1.
struct CudaError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The three brute-force kernels (docs/gpu.md):
//   global — the study's first kernel: each thread loops over every triangle in global memory;
//   shared — the study's second: each block loads tiles of triangle records into shared memory;
//   soa    — rayvec's layout: the tiles are loaded row by row from SoA rows (coalesced).
enum class GpuKernel { global, shared, soa };
inline constexpr GpuKernel kAllGpuKernels[] = {GpuKernel::global, GpuKernel::shared, GpuKernel::soa};
const char* gpu_kernel_name(GpuKernel k);
std::optional<GpuKernel> parse_gpu_kernel(std::string_view name);

// Triangles per shared-memory tile (12 floats each: 1024 fill the 48 KiB a block gets by default).
inline constexpr int kMinTile = 64, kMaxTile = 1024;

struct GpuLaunch {
  GpuKernel kernel = GpuKernel::soa;
  int tile = 256;  // shared and soa only; kMinTile..kMaxTile
};

// Seconds of one query, the transfers apart from the kernel.
struct GpuTimes {
  double upload_s = 0;    // rays (and visibility points) host -> device
  double kernel_s = 0;    // the kernel alone (CUDA events)
  double download_s = 0;  // results device -> host
};

struct CudaDeviceInfo {
  std::string name;
  int major = 0, minor = 0;  // compute capability
  int multiprocessors = 0;
  std::size_t memory_bytes = 0;
};

struct CudaSystem {
  int runtime_version = 0;  // e.g. 13000
  int driver_version = 0;   // 0: no driver
  std::vector<CudaDeviceInfo> devices;
  std::string error;  // why no device is listed, when the runtime says so
};

// Whether this build has the CUDA backend, the toolkit it was built with and the architectures of
// its device code ("" without CUDA).
bool cuda_built();
const char* cuda_toolkit_version();
const char* cuda_architectures();
// Initialises the CUDA runtime (only when asked: `rayvec info`, --device cuda) and lists the devices.
CudaSystem cuda_system();

// The triangles uploaded to device 0, both layouts; queries trace brute force against them.
// Throws CudaError (no device, out of memory, ...).
class CudaTracer {
 public:
  explicit CudaTracer(const GpuTriangles& tris);
  ~CudaTracer();
  CudaTracer(const CudaTracer&) = delete;
  CudaTracer& operator=(const CudaTracer&) = delete;

  const std::string& device_name() const;
  double upload_seconds() const;  // the triangles, host -> device (both layouts)

  // Any hit per ray, 1/0; `ignore` (null, or one point per ray): triangles with a corner at the ray's
  // point are left out (the visibility filter). Same contract as the CPU's trace_occluded.
  std::vector<uint8_t> occluded(std::span<const Ray> rays, const Vec3f* ignore, Intersector intersector,
                                GpuLaunch launch, GpuTimes* times = nullptr);
  // Closest hit per ray, ties to the lowest id. Same contract as the CPU's trace_closest.
  std::vector<Hit> closest(std::span<const Ray> rays, Intersector intersector, GpuLaunch launch,
                           GpuTimes* times = nullptr);

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rayvec::gpu
