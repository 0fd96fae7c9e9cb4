// TileWaves: shades a tile's camera hits generation by generation instead of ray by ray. The camera
// hits are generation 0; the mirror and refraction rays they spawn (Whitted::bounce) make the next
// generation, traced as one stream (Accelerator::closest_stream: 16-ray packets whose lanes that
// part ways finish by single-ray traversal) and lit together (TileLighting: shadow rays as streams, shading
// in SIMD lanes); and so on until no hit spawns a ray. Each hit keeps its local term, its children's
// coefficients and where its children lie in the next generation; last, from the deepest generation up, each
// hit adds its children's radiance to its local term — reflection first, then refraction, as shade() adds
// them — so every pixel gets the bits that Whitted::shade() gives it ray by ray
// (benchmarks.md#decision-tile-waves).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "accel/accelerator.h"
#include "render/bounce_directions.h"
#include "render/render_stats.h"
#include "render/tile_lighting.h"
#include "render/vec3_lanes.h"
#include "render/whitted.h"
#include "scene/scene.h"

namespace rayvec {

// The most rays a generation holds. Trees that would grow a generation past it (glass at a deep
// depth limit with no contribution cutoff doubles its rays at every depth) go on one ray at a
// time, recursively, from the hit that would have passed it: the same bits, memory bounded.
inline constexpr std::size_t kMaxWaveRays = 8192;

class TileWaves {
 public:
  // shade() needs a `whitted` without an observer: an observer follows each ray tree depth first.
  // `max_wave_rays`: the most rays a generation holds (tests set it low).
  TileWaves(const Scene& scene, const Accelerator& accel, const Whitted& whitted,
            std::size_t max_wave_rays = kMaxWaveRays);

  // out[j] = whitted.shade(rays[j], hits[j], 0, 1, counts) for each camera ray of a tile (rays[0 .. n),
  // whose hits `camera` has lit: TileLighting::light(rays, hits, n)) whose hit spawns a ray —
  // camera.lit(j) and not camera.finished(j); out[j] of the others is left as it is. Counts the
  // secondary rays and their shadow rays (the camera hits' shadow rays are the caller's).
  void shade(const Ray* rays, const Hit* hits, int n, const TileLighting& camera, Vec3f* out,
             RayCounts& counts);

 private:
  // One hit of a generation: its radiance (the local term until the children are added), and its
  // children's coefficients and indices in the next generation (-1: none traced).
  struct Node {
    Vec3f radiance;
    Vec3f kr, kt;
    int32_t reflection = -1, refraction = -1;
  };
  // The next generation's rays as they are spawned, reflections and refractions apart (each
  // kind's rays run together), and the weight each carries.
  struct Spawned {
    std::vector<Ray> rays;
    std::vector<float> weights;
    void clear() {
      rays.clear();
      weights.clear();
    }
  };
  // Node k of generation `depth` from its ray, its hit, their lighting (hit j of `lighting`) and
  // its bounce directions; its traced children appended to the spawned lists.
  void expand(const Ray& ray, const Hit& hit, const TileLighting& lighting, int j, int k, int depth,
              float weight, Node& node, RayCounts& counts);
  // The bounce directions of the m nodes of a generation, in SIMD lanes: node k is ray rays[j] and
  // hit j of `lighting`, j = index[k] (index null: j = k). Nodes that spawn nothing get a
  // placeholder.
  void directions(const Ray* rays, const int* index, const TileLighting& lighting, int m);
  BounceDirections direction(int k) const;

  const Accelerator& accel_;
  const Whitted& whitted_;
  const std::size_t max_wave_rays_;
  TileLighting lighting_;   // the secondary generations' (the camera hits' stays with the caller)
  std::vector<int> roots_;  // generation 0's camera rays
  std::vector<std::vector<Node>> nodes_;  // per generation
  Spawned reflections_, refractions_;
  std::vector<Ray> rays_;  // the generation at hand
  std::vector<Hit> hits_;
  std::vector<float> weights_;
  // per material: bounce_directions' index and Fresnel flag
  std::vector<float> ni_;
  std::vector<int32_t> fresnel_model_;
  // per node of the generation at hand: bounce_directions' inputs, then its outputs
  Vec3Lanes ray_dir_, ns_, ng_;
  std::vector<int32_t> entering_, node_fresnel_model_;
  std::vector<float> node_ni_;
  Vec3Lanes dir_, mirror_, refracted_;
  std::vector<float> fresnel_;
  std::vector<int32_t> refracts_;
};

}  // namespace rayvec
