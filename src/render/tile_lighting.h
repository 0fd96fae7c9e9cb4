// TileLighting: the direct light of a tile's camera hits, computed together rather than hit by
// hit. Each hit's surface point comes from Whitted::lit_surface; then, light by light, every hit's
// light sample (light_sample.h) is taken lane by lane over the tile, the shadow rays of the samples
// that face their points go to the accelerator as one stream (Accelerator::occluded_stream:
// packets where their signs agree), and what each unblocked sample adds (Lambert and Blinn–Phong)
// is summed lane by lane; last, each hit's local term (ambient + direct + emission), which is all
// that shade() returns where the material spawns no ray. The lanes do Whitted's arithmetic in its
// order, the lights summed first to last, so the local term, or Whitted::bounce given a hit's
// sum, gives shade()'s bits; only the power in Blinn–Phong's lobe is taken one hit at a time
// (benchmarks.md#decision-tile-lighting).
#pragma once
#include <cstdint>
#include <vector>

#include "accel/accelerator.h"
#include "render/surface_point.h"
#include "render/vec3_lanes.h"
#include "render/whitted.h"
#include "scene/scene.h"

namespace rayvec {

class TileLighting {
 public:
  TileLighting(const Scene& scene, const Accelerator& accel, const Whitted& whitted);

  // Lights the hits of rays[0 .. n): hits[j] is the nearest hit of rays[j].
  void light(const Ray* rays, const Hit* hits, int n);

  // Of hit j of the last light(): whether it is lit (Whitted::lit_surface); if so its surface
  // point and direct light, for Whitted::bounce. Whether it is also finished: its material
  // is Whitted::local_only, and shade() would return radiance(j), the local term.
  bool lit(int j) const { return lit_[j] != 0; }
  const SurfacePoint& surface(int j) const { return surfaces_[j]; }
  Vec3f direct(int j) const { return sum_[j]; }
  bool finished(int j) const { return finished_[j] != 0; }
  Vec3f radiance(int j) const { return radiance_[j]; }
  // The shadow rays the last light() traced.
  uint64_t shadow_rays() const { return shadow_rays_; }

 private:
  // The per-hit lanes of the lit hits (zeros elsewhere): point, normals, shadow-ray origin,
  // direction to the eye, albedo and the highlight's material terms.
  void load_hits(const Ray* rays, const Hit* hits, int n);
  // Light `light`'s samples of every hit: irradiance, Blinn–Phong's cos θh, and whether it faces.
  void sample(const Light& light, int n);
  // The shadow rays of the facing samples, traced together; a blocked sample stops reaching.
  void trace_shadows(const Light& light, int n);
  // What each reaching sample adds, into the sums.
  void add_reaching(int n);

  const Scene& scene_;
  const Accelerator& accel_;
  const Whitted& whitted_;
  std::vector<uint8_t> local_only_;  // per material: Whitted::local_only
  std::vector<SurfacePoint> surfaces_;
  // per hit
  std::vector<int32_t> lit_, finished_, highlight_, specular_;
  Vec3Lanes p_, ng_, ns_, origin_, to_eye_, kd_, ks_, ka_, ke_, sum_, radiance_;
  std::vector<float> ns_exp_;  // the material's Blinn–Phong exponent Ns
  uint64_t shadow_rays_ = 0;
  // per hit, for the light at hand
  Vec3Lanes irradiance_;
  std::vector<float> cos_h_, lobe_;
  std::vector<int32_t> reaches_;  // faces, then faces and not blocked
  std::vector<Ray> shadow_batch_;
  std::vector<uint8_t> blocked_;
  std::vector<int32_t> shadow_hit_;  // the hit of each ray of shadow_batch_
};

}  // namespace rayvec
