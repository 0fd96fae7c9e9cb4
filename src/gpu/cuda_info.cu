// What `rayvec info` reports of CUDA: the toolkit and architectures this build has, and what the
// runtime sees (initialised here, on request only).
#include <cuda_runtime.h>

#include "gpu/cuda_backend.h"

namespace rayvec::gpu {

bool cuda_built() { return true; }
const char* cuda_toolkit_version() { return RAYVEC_CUDA_TOOLKIT; }
const char* cuda_architectures() { return RAYVEC_CUDA_ARCHS; }

CudaSystem cuda_system() {
  CudaSystem s;
  cudaRuntimeGetVersion(&s.runtime_version);
  if (cudaDriverGetVersion(&s.driver_version) != cudaSuccess) s.driver_version = 0;
  int n = 0;
  const cudaError_t e = cudaGetDeviceCount(&n);
  if (e != cudaSuccess) {
    cudaGetLastError();
    s.error = cudaGetErrorString(e);
    return s;
  }
  for (int d = 0; d < n; ++d) {
    cudaDeviceProp p{};
    if (cudaGetDeviceProperties(&p, d) != cudaSuccess) continue;
    s.devices.push_back({p.name, p.major, p.minor, p.multiProcessorCount, p.totalGlobalMem});
  }
  if (s.devices.empty()) s.error = "the driver lists no device";
  return s;
}

}  // namespace rayvec::gpu
