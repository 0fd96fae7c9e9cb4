// Whitted (1980) recursive ray tracing: local lighting (Lambert + Blinn–Phong under point and
// directional lights, with shadow rays), perfect reflection and refraction, with the adaptive depth
// control of Hall & Greenberg (1983): each ray carries the weight it contributes to the pixel, and a
// child whose weight falls below `min_contribution` is not traced. Which of these a hit gets is asked
// of its material's shading model (shaders/shading_model.h).
#pragma once
#include <cstdint>

#include "accel/accelerator.h"
#include "render/bounce_directions.h"
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
  // Whether shade() of a lit hit on m is its local term alone, Ka·ambient + direct light + Ke: m
  // spawns neither a mirror ray nor a refraction ray.
  static bool local_only(const Material& m);

  // What shade() makes of one child ray of a lit hit: traced (into `ray`, with coefficient k and
  // weight), or why not. `none`: the material has no such child.
  enum class Child : uint8_t { none, traced, effect_off, cutoff, total_internal_reflection };
  struct ChildRay {
    Child state = Child::none;
    float weight = 0;  // the child's contribution to the pixel (for a skipped one: what it would carry)
    Vec3f k;           // kr or kt: the child's radiance is multiplied by it
    Ray ray;           // where state is traced
  };
  // A lit hit's local term (Ka·ambient + direct, times the dissolve where it refracts, + Ke) and
  // its children. shade() returns local + reflection.k·L(reflection) + refraction.k·L(refraction),
  // summed in that order, over the traced children (render/tile_waves.h sums them so too).
  struct Bounce {
    Vec3f local;
    ChildRay reflection, refraction;
  };
  // The bounce of a lit hit (lit_surface gave s) reached by `ray` at `depth` carrying `weight`,
  // whose direct light is `direct`.
  Bounce bounce(const Ray& ray, const SurfacePoint& s, Vec3f direct, int depth, float weight) const;
  // The same, given the hit's bounce_directions (render/bounce_directions.h).
  Bounce bounce(const SurfacePoint& s, Vec3f direct, int depth, float weight,
                const BounceDirections& g) const;
  // What shade() returns for a hit at `depth` whose bounce is b: its children traced one ray at a
  // time, recursively, their radiance added to b.local.
  Vec3f finish(const Bounce& b, int depth, RayCounts& rays) const;

 private:
  Vec3f shade_observed(RayKind kind, Vec3f factor, const Ray& ray, const Hit& hit, int depth, float weight,
                       RayCounts& rays) const;
  Vec3f shade_hit(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays) const;
  Vec3f trace(RayKind kind, Vec3f factor, const Ray& ray, int depth, float weight, RayCounts& rays) const;
  void skip(RayKind kind, int depth, float weight) const;
  // Child c of a hit at `depth`: traced and its radiance times c.k added to `radiance`, or its
  // skipping told to the observer.
  void follow(RayKind kind, const ChildRay& c, int depth, Vec3f& radiance, RayCounts& rays) const;
  Vec3f direct_light(const SurfacePoint& s, const Material& m, Vec3f kd, Vec3f to_eye, RayCounts& rays) const;
  bool child_worthwhile(int depth, float weight) const;

  const Scene& scene_;
  const Accelerator& accel_;
  RenderSettings settings_;
  WhittedObserver* observer_;
  const TriangleNormals* normals_;
};

}  // namespace rayvec
