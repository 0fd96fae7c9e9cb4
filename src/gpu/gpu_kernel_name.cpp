#include "gpu/cuda_backend.h"

namespace rayvec::gpu {

const char* gpu_kernel_name(GpuKernel k) {
  switch (k) {
    case GpuKernel::global: return "global";
    case GpuKernel::shared: return "shared";
    case GpuKernel::soa: return "soa";
  }
  return "?";
}

std::optional<GpuKernel> parse_gpu_kernel(std::string_view name) {
  for (GpuKernel k : kAllGpuKernels)
    if (name == gpu_kernel_name(k)) return k;
  return std::nullopt;
}

}  // namespace rayvec::gpu
