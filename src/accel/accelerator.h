// Accelerator: answers closest-hit and any-hit queries over one triangle mesh. `brute` tests every
// triangle (the paper's workload); `bvh` joins as a second implementation of the same interface.
// Every implementation must return the same triangle ids (equal t: lowest id).
// Many rays go through trace_closest / trace_occluded: one call per batch, OpenMP threads over
// groups of stream_rays() rays, each group on the accelerator's stream path (brute force shares
// every triangle load across the group; a BVH traverses packets), never ray by ray
// (benchmarks.md#decision-batched-tracing).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "bvh/counting_traversal.h"
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
  // n rays at once on the calling thread (e.g. a coherent camera tile): hits[k] becomes exactly what
  // closest(rays[k]) returns. The default loops over closest().
  virtual void closest_stream(const Ray* rays, Hit* hits, std::size_t n) const;
  // n rays of a batch in any order (trace_closest's groups), with closest_stream's result. The
  // default is closest_stream; an accelerator whose stream only pays off for coherent rays sends
  // the others ray by ray.
  virtual void closest_group(const Ray* rays, Hit* hits, std::size_t n) const {
    closest_stream(rays, hits, n);
  }
  // n any-hit queries at once on the calling thread: occluded[k] becomes 1 when
  // occluded(rays[k], filters ? &filters[k] : nullptr) is true, else 0. `filters` is null or holds
  // one filter per ray. The default loops over occluded().
  virtual void occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                               const HitFilter* filters = nullptr) const;
  // Rays per stream call that the batch functions hand each thread (a multiple of 16).
  virtual std::size_t stream_rays() const { return 64; }
  // closest() and occluded() (no filter) through a path that counts the work into `cost`: the BVH
  // through the scalar single-ray traversal with counting policies (bvh/counting_traversal.h),
  // whatever ISA the accelerator uses; brute force as every triangle tested. Slower than the plain
  // queries; for the cost AOV and `rayvec trace`. Same results. The defaults (for accelerators
  // without a counting path) answer through closest()/occluded() and count nothing.
  virtual Hit closest_counted(const Ray& ray, TraversalCost& cost) const;
  virtual bool occluded_counted(const Ray& ray, TraversalCost& cost) const;

  virtual std::size_t bytes() const = 0;  // memory held for the triangles and any structure
  virtual const TraceConfig& config() const = 0;
};

std::unique_ptr<Accelerator> make_accelerator(AccelKind kind, const TriangleMesh& mesh,
                                              const TraceConfig& config);

// Whole batches through closest_group / occluded_stream: groups of consecutive rays (at most
// stream_rays(), fewer when that leaves a thread idle) spread over omp_get_max_threads() threads
// (dynamic schedule). Outputs equal the single-ray queries ray by ray. `filters`: null or one per ray.
void trace_closest(const Accelerator& accel, std::span<const Ray> rays, std::span<Hit> hits);
void trace_closest(const Accelerator& accel, const RayBatch& rays, std::span<Hit> hits);
void trace_occluded(const Accelerator& accel, std::span<const Ray> rays, std::span<uint8_t> occluded,
                    const HitFilter* filters = nullptr);
void trace_occluded(const Accelerator& accel, const RayBatch& rays, std::span<uint8_t> occluded);

}  // namespace rayvec
