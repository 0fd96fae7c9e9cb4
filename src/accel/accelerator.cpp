#include "accel/accelerator.h"

#include <stdexcept>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"

namespace rayvec {

const char* accel_name(AccelKind kind) { return kind == AccelKind::bvh ? "bvh" : "brute"; }

std::optional<AccelKind> parse_accel(std::string_view name) {
  if (name == "brute") return AccelKind::brute;
  if (name == "bvh") return AccelKind::bvh;
  return std::nullopt;
}

void Accelerator::closest_stream(const Ray* rays, Hit* hits, std::size_t n) const {
  for (std::size_t i = 0; i < n; ++i) hits[i] = closest(rays[i]);
}

std::unique_ptr<Accelerator> make_accelerator(AccelKind kind, const TriangleMesh& mesh,
                                              const TraceConfig& config) {
  switch (kind) {
    case AccelKind::brute: return std::make_unique<BruteForce>(mesh, config);
    case AccelKind::bvh: return std::make_unique<BvhAccelerator>(mesh, config);
  }
  throw std::invalid_argument("unknown accelerator");
}

void trace_closest(const Accelerator& accel, const RayBatch& rays, std::span<Hit> hits) {
  const auto n = static_cast<std::int64_t>(rays.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (std::int64_t i = 0; i < n; ++i) hits[i] = accel.closest(rays[i]);
}

void trace_occluded(const Accelerator& accel, const RayBatch& rays, std::span<uint8_t> occluded) {
  const auto n = static_cast<std::int64_t>(rays.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (std::int64_t i = 0; i < n; ++i) occluded[i] = accel.occluded(rays[i]) ? 1 : 0;
}

}  // namespace rayvec
