// The CUDA kernels on a real device against the same math run on the host (host_reference.h): every
// kernel, tile sizes at both ends, every device intersector, on the hard-case families and the
// visibility workload — the same ids, t, u and v bit for bit, the same any-hit answers. Skipped,
// saying why, without CUDA in the build or without a device.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "accuracy/hard_cases.h"
#include "gpu/cuda_backend.h"
#include "gpu/host_reference.h"
#include "gpu/visibility_segments.h"

namespace rayvec {
namespace {

constexpr Intersector kDeviceIntersectors[] = {Intersector::mt, Intersector::mt64, Intersector::watertight,
                                               Intersector::watertight64};

bool same_hit(const Hit& a, const Hit& b) {
  return a.tri == b.tri && std::memcmp(&a.t, &b.t, 4) == 0 && std::memcmp(&a.u, &b.u, 4) == 0 &&
         std::memcmp(&a.v, &b.v, 4) == 0;
}

void skip_without_device() {
  if (!gpu::cuda_built()) GTEST_SKIP() << "built without CUDA (configure with -DRAYVEC_CUDA=ON)";
  const gpu::CudaSystem s = gpu::cuda_system();
  if (s.devices.empty()) GTEST_SKIP() << "no CUDA device found (" << s.error << ")";
}

std::vector<gpu::GpuLaunch> launches() {
  std::vector<gpu::GpuLaunch> out{{gpu::GpuKernel::global, 256}};
  for (gpu::GpuKernel k : {gpu::GpuKernel::shared, gpu::GpuKernel::soa})
    for (int tile : {64, 100, 1024}) out.push_back({k, tile});
  return out;
}

TEST(CudaDevice, KernelsMatchTheHostMathBitForBit) {
  skip_without_device();
  if (HasFatalFailure() || IsSkipped()) return;
  for (const HardCaseFamily& f : hard_case_families(2024, 1)) {
    const gpu::GpuTriangles tris = gpu::make_gpu_triangles(f.mesh);
    gpu::CudaTracer tracer(tris);
    for (Intersector i : kDeviceIntersectors) {
      const std::vector<Hit> want = gpu::host_closest(tris, f.rays, i, true);
      const std::vector<uint8_t> want_any = gpu::host_occluded(tris, f.rays, nullptr, i, true);
      for (const gpu::GpuLaunch& l : launches()) {
        const std::vector<Hit> got = tracer.closest(f.rays, i, l);
        const std::vector<uint8_t> any = tracer.occluded(f.rays, nullptr, i, l);
        int differ = 0;
        for (std::size_t r = 0; r < want.size(); ++r) differ += !same_hit(want[r], got[r]);
        EXPECT_EQ(differ, 0) << f.name << " " << intersector_name(i) << " " << gpu::gpu_kernel_name(l.kernel)
                             << " tile " << l.tile;
        EXPECT_EQ(any, want_any) << f.name << " " << intersector_name(i) << " "
                                 << gpu::gpu_kernel_name(l.kernel) << " tile " << l.tile;
      }
    }
  }
}

TEST(CudaDevice, VisibilityMatchesTheHostMath) {
  skip_without_device();
  if (HasFatalFailure() || IsSkipped()) return;
  const TriangleMesh mesh = make_icosphere({0, 0, 0}, 1.0, 4, 3);  // 5120 triangles: several tiles
  const gpu::GpuTriangles tris = gpu::make_gpu_triangles(mesh);
  gpu::CudaTracer tracer(tris);
  const gpu::VisibilitySegments s = gpu::visibility_segments(mesh.positions, {0.3f, -2.5f, 0.2f});
  for (Intersector i : kDeviceIntersectors) {
    const std::vector<uint8_t> want = gpu::host_occluded(tris, s.rays, s.points.data(), i, true);
    for (const gpu::GpuLaunch& l : launches()) {
      gpu::GpuTimes times;
      EXPECT_EQ(tracer.occluded(s.rays, s.points.data(), i, l, &times), want)
          << intersector_name(i) << " " << gpu::gpu_kernel_name(l.kernel) << " tile " << l.tile;
      EXPECT_GT(times.kernel_s, 0.0);
    }
  }
}

}  // namespace
}  // namespace rayvec
