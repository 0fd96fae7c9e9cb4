// TileWaves past its generation cap: the trees that would overfill a generation go on one ray at a
// time from the hit where they would have, and every camera ray still gets Whitted::shade()'s bits.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/camera_rays.h"
#include "render/tile_lighting.h"
#include "render/tile_waves.h"
#include "render/whitted.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

TEST(TileWaves, TreesPastTheGenerationCapShadeAsOneByOne) {
  for (const char* name : {"whitted", "refraction"}) {
    const Scene scene = load_scene(std::string(RAYVEC_SOURCE_DIR) + "/scenes/" + name + ".json");
    const auto accel = make_accelerator(AccelKind::bvh, scene.mesh, TraceConfig{Isa::scalar});
    const Whitted whitted(scene, *accel, scene.render);
    const CameraRays camera(scene.camera);
    // a 32×32 block of the picture's middle, where the glass and the mirrors are
    std::vector<Ray> rays;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        rays.push_back(camera.ray(float(scene.camera.width / 2 - 16 + x) + 0.5f,
                                  float(scene.camera.height / 2 - 16 + y) + 0.5f));
    const int n = int(rays.size());
    std::vector<Hit> hits;
    for (const Ray& r : rays) hits.push_back(accel->closest(r));
    TileLighting lighting(scene, *accel, whitted);
    lighting.light(rays.data(), hits.data(), n);
    for (const std::size_t cap : {std::size_t(1), std::size_t(37), std::size_t(400), kMaxWaveRays}) {
      TileWaves waves(scene, *accel, whitted, cap);
      std::vector<Vec3f> out(static_cast<std::size_t>(n));
      RayCounts by_waves, by_one;
      waves.shade(rays.data(), hits.data(), n, lighting, out.data(), by_waves);
      int spawning = 0;
      for (int j = 0; j < n; ++j) {
        if (!lighting.lit(j) || lighting.finished(j)) continue;
        ++spawning;
        const Vec3f want = whitted.shade(rays[j], hits[j], 0, 1.0f, by_one);
        ASSERT_TRUE(out[j] == want) << name << " cap " << cap << " ray " << j;
      }
      EXPECT_GT(spawning, 50) << name;
      EXPECT_GT(by_one.reflection + by_one.refraction, 400u) << name;
      EXPECT_EQ(by_waves.reflection, by_one.reflection) << name << " cap " << cap;
      EXPECT_EQ(by_waves.refraction, by_one.refraction) << name << " cap " << cap;
    }
  }
}

}  // namespace
}  // namespace rayvec
