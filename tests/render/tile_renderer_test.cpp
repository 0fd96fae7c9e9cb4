// The property a distributed render rests on: tiles rendered one by one, in any order and by any
// renderer, make exactly render()'s image (every channel, bit for bit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "render/renderer.h"
#include "render/tile_renderer.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

TEST(TileRenderer, TilesInAnyOrderMakeRendersImage) {
  Scene scene = load_scene(std::string(RAYVEC_SOURCE_DIR) + "/scenes/whitted.json");
  scene.camera.width = 70;  // edge tiles narrower and shorter than 16
  scene.camera.height = 37;
  RenderSettings settings = scene.render;
  settings.spp = 2;
  settings.aov = {.depth = true, .normal = true, .id = true, .cost = true, .bounces = true};
  const auto accel = make_accelerator(AccelKind::bvh, scene.mesh, TraceConfig{});
  RenderStats stats;
  const Image reference = render(scene, *accel, settings, stats);

  const TileGrid grid(scene.camera.width, scene.camera.height);
  std::vector<int> order(std::size_t(grid.count()));
  for (int i = 0; i < grid.count(); ++i) order[std::size_t(i)] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  const CameraRays camera(scene.camera);
  TileRenderer a(scene, *accel, settings, camera), b(scene, *accel, settings, camera);
  Image image(grid.width, grid.height, render_channel_names(settings.aov));
  const int nc = image.nchannels();
  std::vector<float> tile(std::size_t(kTileSize) * kTileSize * nc);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const TileRect rect = grid.rect(order[k]);
    (k % 2 ? a : b).render(rect, tile.data());
    for (int y = rect.y0; y < rect.y1; ++y)
      std::copy_n(tile.data() + std::size_t(y - rect.y0) * rect.width() * nc, std::size_t(rect.width()) * nc,
                  &image.at(rect.x0, y, 0));
  }
  EXPECT_EQ(image.channels, reference.channels);
  ASSERT_EQ(image.pixels.size(), reference.pixels.size());
  EXPECT_EQ(std::memcmp(image.pixels.data(), reference.pixels.data(), image.pixels.size() * sizeof(float)),
            0);
  RayCounts rays = a.rays;
  rays += b.rays;
  EXPECT_EQ(rays.total(), stats.rays.total());
}

}  // namespace
}  // namespace rayvec
