// The property a distributed render rests on: tiles rendered one by one, in any order and by any
// renderer, make exactly render()'s image (every channel, bit for bit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>

#include "render/pixel_samples.h"
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

// Renders the scene tile by tile and expects every pixel as Whitted::shade() makes it one ray at a
// time, bit for bit, with the same ray counts.
void expect_tiles_shade_as_one_by_one(const Scene& scene, const RenderSettings& settings,
                                      const std::string& label) {
  const auto accel = make_accelerator(AccelKind::bvh, scene.mesh, TraceConfig{Isa::scalar});
  const CameraRays camera(scene.camera);
  TileRenderer tiles(scene, *accel, settings, camera);
  const TileGrid grid(scene.camera.width, scene.camera.height);
  const Whitted whitted(scene, *accel, settings);
  const PixelSamples samples(settings.spp);
  RayCounts one_by_one;
  std::vector<float> tile(std::size_t(kTileSize) * kTileSize * 3);
  for (int t = 0; t < grid.count(); ++t) {
    const TileRect rect = grid.rect(t);
    tiles.render(rect, tile.data());
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) {
        Vec3f sum{};
        for (int s = 0; s < settings.spp; ++s) {
          const auto [sx, sy] = samples.position(PixelSamples::seed(x, y), s);
          const Ray ray = camera.ray(float(x) + sx, float(y) + sy);
          ++one_by_one.primary;
          sum += whitted.shade(ray, accel->closest(ray), 0, 1.0f, one_by_one);
        }
        const Vec3f want = sum * (1.0f / float(settings.spp));
        const float* got = &tile[(std::size_t(y - rect.y0) * rect.width() + (x - rect.x0)) * 3];
        ASSERT_TRUE(got[0] == want.x && got[1] == want.y && got[2] == want.z)
            << label << " pixel " << x << "," << y;
      }
  }
  EXPECT_EQ(tiles.rays.shadow, one_by_one.shadow) << label;
  EXPECT_EQ(tiles.rays.reflection, one_by_one.reflection) << label;
  EXPECT_EQ(tiles.rays.refraction, one_by_one.refraction) << label;
  EXPECT_EQ(tiles.rays.total(), one_by_one.total()) << label;
  if (settings.effects.shadows) {
    EXPECT_GT(one_by_one.shadow, 0u) << label;
  }
}

Scene small_scene(const std::string& name) {
  Scene scene = load_scene(std::string(RAYVEC_SOURCE_DIR) + "/scenes/" + name + ".json");
  scene.camera.width = 37;
  scene.camera.height = 21;
  return scene;
}

// A tile lights its camera hits together, light by light and lane by lane (TileLighting), and
// shades their ray trees generation by generation (TileWaves); each pixel must come out as
// Whitted::shade() makes it one ray at a time — with emission, lights below the floor, without
// power and directional, with many lights, and with shadows off.
TEST(TileRenderer, ShadowRaysTracedTogetherShadeAsOneByOne) {
  for (const char* name : {"whitted", "shadows", "cornell_box", "refraction"}) {
    for (const bool shadows : {true, false}) {
      Scene scene = small_scene(name);
      scene.lights.push_back(Light{Light::Type::point, {0, -50, 0}, {0, -1, 0}, {30, 30, 30}});  // below
      scene.lights.push_back(Light{Light::Type::point, {0, 2, 0}, {0, -1, 0}, {0, 0, 0}});       // no power
      scene.lights.push_back(Light{Light::Type::directional, {}, {0.6f, -0.8f, 0}, {0.5f, 0.5f, 0.5f}});
      for (std::size_t k = 0; k < scene.materials.size(); k += 2)  // emission in the local term's sum
        scene.materials[k].Ke = {0.013f, 0.021f, 0.034f * float(k + 1)};
      if (std::string(name) == "refraction")
        while (scene.lights.size() <= 70)
          scene.lights.push_back(Light{Light::Type::point,
                                       {float(scene.lights.size() % 7) - 3.0f, 5, 2},
                                       {0, -1, 0},
                                       {0.2f, 0.2f, 0.2f}});
      RenderSettings settings = scene.render;
      settings.spp = 3;
      settings.effects.shadows = shadows;
      expect_tiles_shade_as_one_by_one(scene, settings,
                                       std::string(name) + (shadows ? "" : " without shadows"));
    }
  }
}

// The ray trees' generations end where shade()'s recursion does: at the depth limit, under the
// contribution cutoff, at total internal reflection, and where an effect is off; and each hit adds
// its children's radiance in shade()'s order.
TEST(TileRenderer, RayTreesShadedByGenerationShadeAsOneByOne) {
  for (const char* name : {"whitted", "refraction", "reflection"}) {
    const Scene scene = small_scene(name);
    for (int variant = 0; variant < 6; ++variant) {
      RenderSettings settings = scene.render;
      settings.spp = 2;
      std::string label = std::string(name) + " variant " + std::to_string(variant);
      if (variant == 1) settings.max_depth = 1;
      if (variant == 2) settings.max_depth = 3;
      if (variant == 3) settings.min_contribution = 0.3f;
      if (variant == 4) settings.effects.reflection = false;
      if (variant == 5) settings.effects.refraction = false;
      expect_tiles_shade_as_one_by_one(scene, settings, label);
    }
  }
}

}  // namespace
}  // namespace rayvec
