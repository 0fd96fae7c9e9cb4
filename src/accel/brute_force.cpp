#include "accel/brute_force.h"

namespace rayvec {

BruteForce::BruteForce(const TriangleMesh& mesh, const TraceConfig& config)
    : config_(config), tris_(mesh), kernels_(&triangle_kernels(config.isa, config.intersector)) {}

Hit BruteForce::closest(const Ray& ray) const {
  Hit hit;
  kernels_->closest(tris_.arrays(), 0, tris_.size(), ray, hit);
  return hit;
}

bool BruteForce::occluded(const Ray& ray, const HitFilter* filter) const {
  return kernels_->occluded(tris_.arrays(), 0, tris_.size(), ray, filter);
}

}  // namespace rayvec
