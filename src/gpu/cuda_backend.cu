// The CUDA backend: device memory, transfers, the launch of the kernels of trace_kernels.cuh and
// their timing. Device 0 is used; every CUDA error becomes a CudaError naming the call.
#include <cuda_runtime.h>

#include <chrono>
#include <string>
#include <type_traits>

#include "gpu/cuda_backend.h"
#include "gpu/math_dispatch.h"
#include "gpu/trace_kernels.cuh"

namespace rayvec::gpu {
namespace {

void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) {
    cudaGetLastError();  // clear a non-sticky error so a later query starts clean
    throw CudaError(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Device memory of `bytes`, freed with the object.
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  explicit DeviceBuffer(std::size_t bytes) {
    if (bytes) check(cudaMalloc(&p_, bytes), "cudaMalloc");
  }
  ~DeviceBuffer() {
    if (p_) cudaFree(p_);
  }
  DeviceBuffer(DeviceBuffer&& o) noexcept : p_(o.p_) { o.p_ = nullptr; }
  DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
    std::swap(p_, o.p_);
    return *this;
  }
  template <class T>
  T* as() const {
    return static_cast<T*>(p_);
  }

 private:
  void* p_ = nullptr;
};

DeviceBuffer upload(const void* data, std::size_t bytes) {
  DeviceBuffer b(bytes);
  if (bytes) check(cudaMemcpy(b.as<void>(), data, bytes, cudaMemcpyHostToDevice), "upload");
  return b;
}

// Two events around a kernel.
struct EventPair {
  cudaEvent_t start = nullptr, stop = nullptr;
  EventPair() {
    check(cudaEventCreate(&start), "cudaEventCreate");
    check(cudaEventCreate(&stop), "cudaEventCreate");
  }
  ~EventPair() {
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
  }
  double seconds() const {
    float ms = 0;
    check(cudaEventElapsedTime(&ms, start, stop), "cudaEventElapsedTime");
    return ms * 1e-3;
  }
};

template <class Math, bool AnyHit>
void launch(const KernelArgs& a, GpuLaunch launch) {
  const unsigned blocks = (a.ray_count + kThreadsPerBlock - 1) / kThreadsPerBlock;
  const std::size_t shared = std::size_t(launch.tile) * kTriangleRows * sizeof(float);
  switch (launch.kernel) {
    case GpuKernel::global: global_kernel<Math, AnyHit><<<blocks, kThreadsPerBlock>>>(a); break;
    case GpuKernel::shared: tiled_kernel<Math, AnyHit, false><<<blocks, kThreadsPerBlock, shared>>>(a); break;
    case GpuKernel::soa: tiled_kernel<Math, AnyHit, true><<<blocks, kThreadsPerBlock, shared>>>(a); break;
  }
}

}  // namespace

struct CudaTracer::Impl {
  std::string device;
  double upload_s = 0;
  uint32_t count = 0, row_length = 0;
  DeviceBuffer aos, soa;

  // Rays up, the kernel, results down; each part timed.
  template <bool AnyHit, class Out>
  void run(std::span<const Ray> rays, const Vec3f* ignore, Intersector intersector, GpuLaunch launch_as,
           Out* out, GpuTimes* times) {
    if (!device_supports(intersector))
      throw CudaError(std::string("intersector ") + intersector_name(intersector) + " is not on the device");
    if (launch_as.tile < kMinTile || launch_as.tile > kMaxTile)
      throw CudaError("tile size " + std::to_string(launch_as.tile) + " outside 64..1024");
    GpuTimes t;
    if (!rays.empty()) {
      auto start = std::chrono::steady_clock::now();
      const std::vector<GpuRay> host_rays = to_gpu_rays(rays);
      DeviceBuffer d_rays = upload(host_rays.data(), host_rays.size() * sizeof(GpuRay));
      DeviceBuffer d_ignore;
      if (ignore) {
        std::vector<float> points(rays.size() * 3);
        for (std::size_t k = 0; k < rays.size(); ++k) {
          points[3 * k] = ignore[k].x;
          points[3 * k + 1] = ignore[k].y;
          points[3 * k + 2] = ignore[k].z;
        }
        d_ignore = upload(points.data(), points.size() * sizeof(float));
      }
      DeviceBuffer d_out(rays.size() * sizeof(Out));
      t.upload_s = seconds_since(start);

      KernelArgs a{aos.as<float>(),
                   soa.as<float>(),
                   count,
                   row_length,
                   d_rays.as<GpuRay>(),
                   ignore ? d_ignore.as<float>() : nullptr,
                   uint32_t(rays.size()),
                   uint32_t(launch_as.tile),
                   AnyHit ? d_out.as<uint8_t>() : nullptr,
                   AnyHit ? nullptr : d_out.as<GpuHit>()};
      EventPair events;
      check(cudaEventRecord(events.start), "cudaEventRecord");
      visit_math<true>(intersector, [&](auto math) { launch<decltype(math), AnyHit>(a, launch_as); });
      check(cudaGetLastError(), "kernel launch");
      check(cudaEventRecord(events.stop), "cudaEventRecord");
      check(cudaEventSynchronize(events.stop), "kernel");
      t.kernel_s = events.seconds();

      start = std::chrono::steady_clock::now();
      check(cudaMemcpy(out, d_out.as<void>(), rays.size() * sizeof(Out), cudaMemcpyDeviceToHost), "download");
      t.download_s = seconds_since(start);
    }
    if (times) *times = t;
  }
};

CudaTracer::CudaTracer(const GpuTriangles& tris) : impl_(std::make_unique<Impl>()) {
  int devices = 0;
  const cudaError_t e = cudaGetDeviceCount(&devices);
  if (e != cudaSuccess || devices == 0) {
    cudaGetLastError();
    throw CudaError(std::string("no CUDA device found (") +
                    (e != cudaSuccess ? cudaGetErrorString(e) : "the driver lists none") + ")");
  }
  check(cudaSetDevice(0), "cudaSetDevice");
  cudaDeviceProp prop{};
  check(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
  impl_->device = prop.name;
  check(cudaFree(nullptr), "context creation");  // the context now, not inside the first timing
  const auto start = std::chrono::steady_clock::now();
  impl_->count = tris.count;
  impl_->row_length = tris.row_length;
  impl_->aos = upload(tris.aos.data(), tris.aos.size() * sizeof(float));
  impl_->soa = upload(tris.soa.data(), tris.soa.size() * sizeof(float));
  impl_->upload_s = seconds_since(start);
}

CudaTracer::~CudaTracer() = default;

const std::string& CudaTracer::device_name() const { return impl_->device; }
double CudaTracer::upload_seconds() const { return impl_->upload_s; }

std::vector<uint8_t> CudaTracer::occluded(std::span<const Ray> rays, const Vec3f* ignore,
                                          Intersector intersector, GpuLaunch launch, GpuTimes* times) {
  std::vector<uint8_t> out(rays.size());
  impl_->run<true>(rays, ignore, intersector, launch, out.data(), times);
  return out;
}

std::vector<Hit> CudaTracer::closest(std::span<const Ray> rays, Intersector intersector, GpuLaunch launch,
                                     GpuTimes* times) {
  std::vector<GpuHit> hits(rays.size());
  impl_->run<false>(rays, nullptr, intersector, launch, hits.data(), times);
  std::vector<Hit> out(rays.size());
  for (std::size_t k = 0; k < hits.size(); ++k) out[k] = to_hit(hits[k]);
  return out;
}

}  // namespace rayvec::gpu
