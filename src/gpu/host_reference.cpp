#include "gpu/host_reference.h"

#include <stdexcept>

#include "gpu/math_dispatch.h"
#include "gpu/trace_loops.h"

namespace rayvec::gpu {
namespace {

struct AosAt {
  const GpuTriangles* t;
  TriangleView operator()(uint32_t i) const { return t->aos_view(i); }
};
struct SoaAt {
  const GpuTriangles* t;
  TriangleView operator()(uint32_t i) const { return t->soa_view(i); }
};

template <bool Fused, class F>
void visit_or_throw(Intersector i, F&& f) {
  if (!visit_math<Fused>(i, f))
    throw std::invalid_argument(std::string("intersector ") + intersector_name(i) + " has no device math");
}

template <bool Fused, class F>
void with_layout_and_math(Intersector i, HostLayout layout, const GpuTriangles& tris, F&& f) {
  visit_or_throw<Fused>(i, [&](auto math) {
    if (layout == HostLayout::aos)
      f(math, AosAt{&tris});
    else
      f(math, SoaAt{&tris});
  });
}

template <bool Fused>
std::vector<Hit> closest_all(const GpuTriangles& tris, std::span<const Ray> rays, Intersector i,
                             HostLayout layout) {
  std::vector<Hit> hits(rays.size());
  with_layout_and_math<Fused>(i, layout, tris, [&](auto math, auto at) {
    using Math = decltype(math);
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const GpuRay g = to_gpu_ray(rays[k]);
      const typename Math::Ray r = Math::prepare(g);
      ClosestState<Math> best = closest_start<Math>(g);
      if (r.valid) closest_range<Math>(r, at, 0, tris.count, 0, best);
      hits[k] = to_hit(closest_finish<Math>(best));
    }
  });
  return hits;
}

template <bool Fused>
std::vector<uint8_t> occluded_all(const GpuTriangles& tris, std::span<const Ray> rays, const Vec3f* ignore,
                                  Intersector i, HostLayout layout) {
  std::vector<uint8_t> out(rays.size());
  with_layout_and_math<Fused>(i, layout, tris, [&](auto math, auto at) {
    using Math = decltype(math);
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const GpuRay g = to_gpu_ray(rays[k]);
      const typename Math::Ray r = Math::prepare(g);
      const float point[3] = {ignore ? ignore[k].x : 0.0f, ignore ? ignore[k].y : 0.0f,
                              ignore ? ignore[k].z : 0.0f};
      out[k] = r.valid &&
               occluded_range<Math>(r, occluded_limit<Math>(g), at, 0, tris.count, ignore ? point : nullptr);
    }
  });
  return out;
}

}  // namespace

std::vector<Hit> host_closest(const GpuTriangles& tris, std::span<const Ray> rays, Intersector intersector,
                              bool fused, HostLayout layout) {
  return fused ? closest_all<true>(tris, rays, intersector, layout)
               : closest_all<false>(tris, rays, intersector, layout);
}

std::vector<uint8_t> host_occluded(const GpuTriangles& tris, std::span<const Ray> rays, const Vec3f* ignore,
                                   Intersector intersector, bool fused, HostLayout layout) {
  return fused ? occluded_all<true>(tris, rays, ignore, intersector, layout)
               : occluded_all<false>(tris, rays, ignore, intersector, layout);
}

}  // namespace rayvec::gpu
