// make_embree_tracer when rayvec is built without Embree (CMake compiles embree_rival_embree.cpp
// only when it finds Embree 3).
#ifndef RAYVEC_HAVE_EMBREE
#include "bench/ray_tracer.h"

namespace rayvec {

bool embree_available() { return false; }

std::unique_ptr<RayTracer> make_embree_tracer(const TriangleMesh&, int, const char*, double& build_seconds) {
  build_seconds = 0;
  return nullptr;
}

}  // namespace rayvec
#endif
