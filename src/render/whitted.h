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

  // What a light gives a surface point before any shadow (light_samples): nothing unless `faces`
  // (the light has power and lies on the lit side of both normals); then the direction to it, its
  // irradiance, the cosine at the shading normal and the shadow ray toward it.
  struct LightSample {
    Vec3f to_light, irradiance;
    float cos_s;
    Ray shadow;
    bool faces;
  };

  // A primary hit shaded in two steps, so that a tile's shadow rays go to the accelerator together
  // (Accelerator::occluded_stream, as packets where they are coherent) instead of one by one. The
  // results come through out-parameters: copies of returned structs read back in other widths
  // would stall store forwarding once per hit.
  // The surface point of a hit that shade() lights into s; false (s unspecified) for a miss or an
  // unlit material, where shade() traces no shadow ray.
  bool lit_surface(const Ray& ray, const Hit& hit, SurfacePoint& s) const;
  // Every light's sample at s into out[0 .. scene.lights.size()). The shadow rays shade() traces are
  // those of the samples that face s, when the settings allow shadows (shadows_on()).
  void light_samples(const SurfacePoint& s, LightSample* out) const;
  bool shadows_on() const { return settings_.effects.shadows; }
  // shade(ray, hit, 0, 1, rays) for a hit whose lit_surface is s and whose light_samples are
  // `samples`, where light li's shadow ray is blocked when blocked[li] is nonzero (read only for the
  // samples that face s). The same radiance, ray counts and observer calls as shade().
  Vec3f shade_primary(const Ray& ray, const Hit& hit, const SurfacePoint& s, const LightSample* samples,
                      const uint8_t* blocked, RayCounts& rays) const;

 private:
  void light_sample(const SurfacePoint& s, Vec3f origin, const Light& light, LightSample& l) const;
  Vec3f shade_observed(RayKind kind, Vec3f factor, const Ray& ray, const Hit& hit, int depth, float weight,
                       RayCounts& rays) const;
  // `lit` (if not null): the hit's surface point, light samples and shadow answers, as shade_primary's.
  struct Precomputed {
    const SurfacePoint& s;
    const LightSample* samples;
    const uint8_t* blocked;
  };
  Vec3f shade_hit(const Ray& ray, const Hit& hit, int depth, float weight, RayCounts& rays,
                  const Precomputed* lit = nullptr) const;
  Vec3f trace(RayKind kind, Vec3f factor, const Ray& ray, int depth, float weight, RayCounts& rays) const;
  void skip(RayKind kind, int depth, float weight) const;
  Vec3f direct_light(const SurfacePoint& s, const Material& m, Vec3f kd, Vec3f to_eye, RayCounts& rays,
                     const Precomputed* lit) const;
  bool child_worthwhile(int depth, float weight) const;

  const Scene& scene_;
  const Accelerator& accel_;
  RenderSettings settings_;
  WhittedObserver* observer_;
  const TriangleNormals* normals_;
};

}  // namespace rayvec
