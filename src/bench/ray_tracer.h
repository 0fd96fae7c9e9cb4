// RayTracer: what `rayvec bench rays` times — rayvec's accelerator or a rival (Embree) behind one
// interface, so both trace the very same rays through the very same timing loop.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "rays/ray.h"

namespace rayvec {

class Accelerator;
struct TriangleMesh;

class RayTracer {
 public:
  virtual ~RayTracer() = default;
  virtual std::string name() const = 0;
  // n independent rays, one query each (single-ray API).
  virtual void closest(const Ray* rays, Hit* hits, std::size_t n) const = 0;
  // One coherent packet of n <= 16 rays (a 4×4 tile).
  virtual void closest_packet(const Ray* rays, Hit* hits, std::size_t n) const = 0;
  // n independent any-hit queries.
  virtual void occluded(const Ray* rays, uint8_t* out, std::size_t n) const = 0;
  // Any-hit queries of one packet of n <= 16 rays (the shadow rays of a 4×4 tile's hits).
  virtual void occluded_packet(const Ray* rays, uint8_t* out, std::size_t n) const = 0;
};

// rayvec's accelerator: closest(), closest_stream() for packets, occluded(), occluded_stream() for
// any-hit packets.
std::unique_ptr<RayTracer> make_accelerator_tracer(const Accelerator& accel);

// Embree 3 with RTC_BUILD_QUALITY_HIGH, `threads` build threads, its ISA capped at `max_isa`
// (Embree's names: "sse2", "avx2", "avx512"; see embree_max_isa): rtcIntersect1, rtcIntersect16,
// rtcOccluded1, rtcOccluded16, run inside librayvec_embree.so (loaded on first use). Null when rayvec was
// built without Embree; throws RuntimeError when the module cannot be loaded or Embree fails. build_seconds
// receives the time of rtcCommitScene.
std::unique_ptr<RayTracer> make_embree_tracer(const TriangleMesh& mesh, int threads, const char* max_isa,
                                              double& build_seconds);
// Whether make_embree_tracer can run; if not, why (built without Embree, module not found or
// not loadable), else empty.
bool embree_available();
std::string embree_unavailable_reason();
// Whether this rayvec was built with Embree (then a missing module is a runtime failure, not a
// choice of the build).
bool embree_built();

}  // namespace rayvec
