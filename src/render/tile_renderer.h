// TileRenderer: renders one 16×16 tile of the image at a time, the unit that render() hands to its
// OpenMP threads and that a distributed render deals to its ranks. A pixel's value depends only on
// the pixel (its samples are hashed from (x, y, s), see PixelSamples), never on which thread,
// rank or order renders its tile, so every way of dealing tiles gives the same image, bit for bit.
#pragma once
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "render/camera_rays.h"
#include "render/pixel_cost.h"
#include "render/pixel_samples.h"
#include "render/render_stats.h"
#include "render/tile_lighting.h"
#include "render/tile_waves.h"
#include "render/whitted.h"
#include "scene/scene.h"

namespace rayvec {

inline constexpr int kTileSize = 16;

struct TileRect {
  int x0, y0, x1, y1;  // pixels [x0, x1) × [y0, y1)
  int width() const { return x1 - x0; }
  int pixels() const { return (x1 - x0) * (y1 - y0); }
};

// The tiles of a width × height image in row-major order.
struct TileGrid {
  int width = 0, height = 0, tiles_x = 0, tiles_y = 0;
  TileGrid(int w, int h)
      : width(w),
        height(h),
        tiles_x((w + kTileSize - 1) / kTileSize),
        tiles_y((h + kTileSize - 1) / kTileSize) {}
  int count() const { return tiles_x * tiles_y; }
  TileRect rect(int tile) const {
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    return {x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height)};
  }
};

// The image channels of a render with these AOVs: R, G, B, then Z, N.x..N.z, id, object_id,
// cost.nodes, cost.triangles, bounces as asked.
std::vector<std::string> render_channel_names(const RenderSettings::Aovs& aov);

// One per thread (it holds the thread's scratch buffers and counters).
class TileRenderer {
 public:
  // `normals`: the scene's TriangleNormals (surface_point), or null.
  TileRenderer(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
               const CameraRays& camera, const TriangleNormals* normals = nullptr);

  // Every channel of the tile's pixels into `out`: rect.pixels() × channels floats, pixel-major, rows
  // top to bottom. Adds to rays, primary_seconds and shading_seconds.
  void render(const TileRect& rect, float* out);

  RayCounts rays;
  double primary_seconds = 0, shading_seconds = 0;  // thread-seconds: closest_stream, and the rest

 private:
  const Scene& scene_;
  const Accelerator& accel_;
  const RenderSettings& settings_;
  const CameraRays& camera_;
  const TriangleNormals* normals_;
  const int channels_;
  const bool counting_;
  PixelCost pixel_cost_;
  Whitted whitted_;
  PixelSamples samples_;
  std::vector<int> block_order_;  // the tile's pixels by 4×4 blocks: the order of batch_ and hits_
  std::vector<uint32_t> seeds_;   // in block order: each pixel's PixelSamples::seed
  std::vector<float> pixel_x_, pixel_y_, sample_x_, sample_y_;  // pixel corners, sample positions
  std::vector<Ray> batch_;
  std::vector<Hit> hits_;
  // The camera hits' direct light, computed together, and their ray trees shaded generation by
  // generation; renders that count each pixel's rays (an observer) shade them one by one instead.
  TileLighting lighting_;
  TileWaves waves_;
  std::vector<Vec3f> radiance_;  // in block order
  std::vector<Vec3f> sum_;
  std::vector<TraversalCost> costs_;
  std::vector<int> bounces_;
};

}  // namespace rayvec
