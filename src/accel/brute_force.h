// BruteForce: every ray against every triangle, W triangles per SIMD step — the paper's workload.
#pragma once
#include "accel/accelerator.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {

class BruteForce final : public Accelerator {
 public:
  BruteForce(const TriangleMesh& mesh, const TraceConfig& config);

  Hit closest(const Ray& ray) const override;
  bool occluded(const Ray& ray, const HitFilter* filter = nullptr) const override;
  Hit closest_counted(const Ray& ray, TraversalCost& cost) const override;
  bool occluded_counted(const Ray& ray, TraversalCost& cost) const override;
  // Cache-blocked over the triangles (closest_batch): every ray of the batch per triangle chunk.
  void closest_stream(const Ray* rays, Hit* hits, std::size_t n) const override;
  // The same tiling for any-hit queries (occluded_batch): a ray stops at its first hit.
  void occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                       const HitFilter* filters = nullptr) const override;
  std::size_t bytes() const override { return tris_.bytes(); }
  const TraceConfig& config() const override { return config_; }

 private:
  TraceConfig config_;
  TriangleSoA tris_;
  const TriangleKernels* kernels_;
};

}  // namespace rayvec
