#include "accel/brute_force.h"

#include "kernels/closest_batch.h"

namespace rayvec {

BruteForce::BruteForce(const TriangleMesh& mesh, const TraceConfig& config)
    : config_(config),
      // the normals only the float `mt` kernels read
      tris_(mesh, {}, config.intersector == Intersector::mt ? Normals::stored : Normals::formed),
      kernels_(&triangle_kernels(config.isa, config.intersector)) {}

Hit BruteForce::closest(const Ray& ray) const {
  Hit hit;
  kernels_->closest(tris_.arrays(), 0, tris_.size(), ray, hit);
  return hit;
}

void BruteForce::closest_stream(const Ray* rays, Hit* hits, std::size_t n) const {
  for (std::size_t k = 0; k < n; ++k) hits[k] = Hit{};
  closest_batch(*kernels_, tris_.arrays(), 0, tris_.size(), rays, hits, n);
}

void BruteForce::occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                                 const HitFilter* filters) const {
  occluded_batch(*kernels_, tris_.arrays(), 0, tris_.size(), rays, occluded, n, filters);
}

bool BruteForce::occluded(const Ray& ray, const HitFilter* filter) const {
  return kernels_->occluded(tris_.arrays(), 0, tris_.size(), ray, filter);
}

Hit BruteForce::closest_counted(const Ray& ray, TraversalCost& cost) const {
  cost.triangles += tris_.size();
  return closest(ray);
}

bool BruteForce::occluded_counted(const Ray& ray, TraversalCost& cost) const {
  cost.triangles += tris_.size();  // an upper bound: the kernel may stop at the first hit
  return occluded(ray);
}

}  // namespace rayvec
