// The CUDA backend of a build without CUDA: every entry says so (the front end turns that into exit
// status 2, "built without CUDA", before getting here).
#include "gpu/cuda_backend.h"

namespace rayvec::gpu {

struct CudaTracer::Impl {};

bool cuda_built() { return false; }
const char* cuda_toolkit_version() { return ""; }
const char* cuda_architectures() { return ""; }
CudaSystem cuda_system() { return CudaSystem{0, 0, {}, "built without CUDA"}; }

CudaTracer::CudaTracer(const GpuTriangles&) {
  throw CudaError("this rayvec was built without CUDA (configure with -DRAYVEC_CUDA=ON)");
}
CudaTracer::~CudaTracer() = default;
const std::string& CudaTracer::device_name() const {
  static const std::string none;
  return none;
}
double CudaTracer::upload_seconds() const { return 0; }
std::vector<uint8_t> CudaTracer::occluded(std::span<const Ray>, const Vec3f*, Intersector, GpuLaunch,
                                          GpuTimes*) {
  return {};
}
std::vector<Hit> CudaTracer::closest(std::span<const Ray>, Intersector, GpuLaunch, GpuTimes*) { return {}; }

}  // namespace rayvec::gpu
