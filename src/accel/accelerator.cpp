#include "accel/accelerator.h"

#include <omp.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"

namespace rayvec {
namespace {

// Rays per work item: stream_rays(), or fewer (a multiple of 16, the widest packet) when a batch of
// few rays would otherwise leave threads without work.
std::size_t group_size(const Accelerator& accel, std::size_t n) {
  const std::size_t threads = std::size_t(std::max(omp_get_max_threads(), 1));
  const std::size_t even = (n + threads - 1) / threads;
  return std::clamp((even + 15) / 16 * 16, std::size_t(16), std::max(accel.stream_rays(), std::size_t(16)));
}

// fn(begin, count) for consecutive groups of rays covering [0, n), OpenMP-dynamic over groups.
template <typename Fn>
void for_each_group(const Accelerator& accel, std::size_t n, Fn&& fn) {
  const std::size_t group = group_size(accel, n);
  const auto groups = static_cast<std::int64_t>((n + group - 1) / group);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t g = 0; g < groups; ++g) {
    const std::size_t begin = std::size_t(g) * group;
    fn(begin, std::min(group, n - begin));
  }
}

// rays[begin, begin + count) of a structure-of-arrays batch as Ray records.
void gather(const RayBatch& rays, std::size_t begin, std::size_t count, std::vector<Ray>& out) {
  out.resize(count);
  for (std::size_t k = 0; k < count; ++k) out[k] = rays[begin + k];
}

}  // namespace

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

void Accelerator::occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                                  const HitFilter* filters) const {
  for (std::size_t i = 0; i < n; ++i) occluded[i] = this->occluded(rays[i], filters ? &filters[i] : nullptr);
}

void trace_closest(const Accelerator& accel, std::span<const Ray> rays, std::span<Hit> hits) {
  for_each_group(accel, rays.size(), [&](std::size_t begin, std::size_t count) {
    accel.closest_group(rays.data() + begin, hits.data() + begin, count);
  });
}

void trace_closest(const Accelerator& accel, const RayBatch& rays, std::span<Hit> hits) {
  for_each_group(accel, rays.size(), [&](std::size_t begin, std::size_t count) {
    thread_local std::vector<Ray> group;
    gather(rays, begin, count, group);
    accel.closest_group(group.data(), hits.data() + begin, count);
  });
}

void trace_occluded(const Accelerator& accel, std::span<const Ray> rays, std::span<uint8_t> occluded,
                    const HitFilter* filters) {
  for_each_group(accel, rays.size(), [&](std::size_t begin, std::size_t count) {
    accel.occluded_stream(rays.data() + begin, occluded.data() + begin, count,
                          filters ? filters + begin : nullptr);
  });
}

void trace_occluded(const Accelerator& accel, const RayBatch& rays, std::span<uint8_t> occluded) {
  for_each_group(accel, rays.size(), [&](std::size_t begin, std::size_t count) {
    thread_local std::vector<Ray> group;
    gather(rays, begin, count, group);
    accel.occluded_stream(group.data(), occluded.data() + begin, count);
  });
}

Hit Accelerator::closest_counted(const Ray& ray, TraversalCost&) const { return closest(ray); }

bool Accelerator::occluded_counted(const Ray& ray, TraversalCost&) const { return occluded(ray); }

}  // namespace rayvec
