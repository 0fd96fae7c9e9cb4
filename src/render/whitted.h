// Whitted (1980) recursive ray tracing: local lighting (Lambert + Blinn–Phong under point and
// directional lights, with shadow rays), perfect reflection and refraction, with the adaptive depth
// control of Hall & Greenberg (1983): each ray carries the weight it contributes to the pixel, and a
// child whose weight falls below `min_contribution` is not traced. Which of these a hit gets is asked
// of its material's shading model (shaders/shading_model.h).
#pragma once
#include "accel/accelerator.h"
#include "render/render_stats.h"
#include "render/surface_point.h"
#include "render/whitted_observer.h"
#include "scene/scene.h"

namespace rayvec {

class Whitted {
 public:
  // Reads max_depth, min_contribution and effects of `settings`. `observer`, if not null, is told
  // about every ray (render/whitted_observer.h); it does not change the arithmetic, so the radiance
  // is the same with or without one.
  // `normals`, if not null, holds the scene's TriangleNormals (surface_point).
  Whitted(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
          WhittedObserver* observer = nullptr, const TriangleNormals* normals = nullptr)
      : scene_(scene), accel_(accel), settings_(settings), observer_(observer), normals_(normals) {}

  // Radiance arriving along `ray` whose nearest hit is `hit` (already traced). `weight` is the
  // ray's contribution to its pixel (1 for primary rays). Counts the rays it spawns in `rays`.
  Vec3f shade(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays) const;

  // The surface point of a hit that shade() lights into s; false (s unspecified) for a miss or an
  // unlit material, where shade() computes no direct light.
  bool lit_surface(const Ray& ray, const Hit& hit, SurfacePoint& s) const;
  bool shadows_on() const { return settings_.effects.shadows; }
  // A camera hit lit beforehand (render/tile_lighting.h), for a Whitted without an observer: the
  // hit's lit_surface is s and its direct light (what its unblocked light samples add) `direct`.
  // The same radiance and ray counts as shade(ray, hit, 0, 1, rays), less the shadow rays, which
  // their tracer counts.
  Vec3f shade_primary(const Ray& ray, const Hit& hit, const SurfacePoint& s, Vec3f direct,
                      RayCounts& rays) const;
  // Whether shade() of a lit hit on m is its local term alone, Ka·ambient + direct light + Ke: m
  // spawns neither a mirror ray nor a refraction ray.
  static bool local_only(const Material& m);

 private:
  Vec3f shade_observed(RayKind kind, Vec3f factor, const Ray& ray, const Hit& hit, int depth, float weight,
                       RayCounts& rays) const;
  // `lit` (if not null): the hit's surface point and direct light, as shade_primary's.
  struct Precomputed {
    const SurfacePoint& s;
    Vec3f direct;
  };
  Vec3f shade_hit(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays,
                  const Precomputed* lit = nullptr) const;
  Vec3f trace(RayKind kind, Vec3f factor, const Ray& ray, int depth, float weight, RayCounts& rays) const;
  void skip(RayKind kind, int depth, float weight) const;
  Vec3f direct_light(const SurfacePoint& s, const Material& m, Vec3f kd, Vec3f to_eye, RayCounts& rays) const;
  bool child_worthwhile(int depth, float weight) const;

  const Scene& scene_;
  const Accelerator& accel_;
  RenderSettings settings_;
  WhittedObserver* observer_;
  const TriangleNormals* normals_;
};

}  // namespace rayvec
