// Accelerator: answers closest-hit and any-hit queries over one triangle mesh. `brute` tests every
// triangle (the paper's workload); `bvh` joins as a second implementation of the same interface.
// Every implementation must return the same triangle ids (equal t: lowest id).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "kernels/intersector.h"
#include "platform/isa.h"
#include "kernels/triangle_kernels.h"
#include "rays/ray.h"

namespace rayvec {

struct TriangleMesh;

enum class AccelKind { brute, bvh };
const char* accel_name(AccelKind kind);
std::optional<AccelKind> parse_accel(std::string_view name);

struct TraceConfig {
  Isa isa = Isa::scalar;
  Intersector intersector = Intersector::mt;
};

class Accelerator {
 public:
  virtual ~Accelerator() = default;

  // Nearest hit with tmin <= t <= tmax; a miss is {tri = -1, t = inf}. Thread-safe.
  virtual Hit closest(const Ray& ray) const = 0;
  // True when any triangle is hit with tmin <= t <= tmax and not ignored by `filter` (may be null).
  // Thread-safe.
  virtual bool occluded(const Ray& ray, const HitFilter* filter = nullptr) const = 0;
  // n rays at once (e.g. a coherent camera tile); the default loops over closest().
  virtual void closest_stream(const Ray* rays, Hit* hits, std::size_t n) const;

  virtual std::size_t bytes() const = 0;  // memory held for the triangles and any structure
  virtual const TraceConfig& config() const = 0;
};

std::unique_ptr<Accelerator> make_accelerator(AccelKind kind, const TriangleMesh& mesh,
                                              const TraceConfig& config);

// Whole batches, OpenMP-parallel over rays (dynamic schedule, omp_get_max_threads() threads).
void trace_closest(const Accelerator& accel, const RayBatch& rays, std::span<Hit> hits);
void trace_occluded(const Accelerator& accel, const RayBatch& rays, std::span<uint8_t> occluded);

}  // namespace rayvec
