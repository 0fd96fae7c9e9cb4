// CameraRays::rays (four rays in SSE lanes) against CameraRays::ray (one at a time): the same bits for
// every camera and position, and PixelSamples against the formula it stands for.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <vector>

#include "render/camera_rays.h"
#include "render/pixel_samples.h"

namespace rayvec {
namespace {

Camera camera(Vec3f eye, Vec3f look_at, Vec3f up, float fov_y, int width, int height) {
  Camera c;
  c.eye = eye;
  c.look_at = look_at;
  c.up = up;
  c.fov_y = fov_y;
  c.width = width;
  c.height = height;
  return c;
}

bool same_bits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

TEST(CameraRays, BatchGivesEachRaysBitsForEveryCameraAndPosition) {
  const Camera cameras[] = {
      camera({0, 1, 5}, {0, 1, 0}, {0, 1, 0}, 45.0f, 640, 480),
      camera({3.7f, -2.1f, 0.3f}, {-1.3f, 0.2f, 9.1f}, {0.1f, 0.9f, 0.3f}, 27.5f, 1920, 1080),
      camera({1e4f, 2e4f, -3e4f}, {0, 0, 0}, {0, 0, 1}, 120.0f, 33, 17),
      camera({0, 0, 0}, {0, -1, 1e-3f}, {0, 1, 0}, 1.0f, 7, 4000),
  };
  std::mt19937 rng(11);
  for (const Camera& c : cameras) {
    const CameraRays cam(c);
    for (int n : {0, 1, 3, 4, 5, 8, 255, 256, 1000}) {
      std::vector<float> px(n), py(n);
      for (int i = 0; i < n; ++i) {
        // Pixel corners, centres, jittered positions, the top and left edges and the far corner.
        const int kind = int(rng() % 6);
        const float x = float(rng() % uint32_t(c.width)), y = float(rng() % uint32_t(c.height));
        const float jx = float(rng() >> 8) / 16777216.0f, jy = float(rng() >> 8) / 16777216.0f;
        const float corners[4][2] = {
            {x, y}, {x + 0.5f, y + 0.5f}, {x + jx, y + jy}, {float(c.width) * jx, 0.0f}};
        px[i] = kind < 4 ? corners[kind][0] : kind == 4 ? 0.0f : float(c.width);
        py[i] = kind < 4 ? corners[kind][1] : kind == 4 ? float(c.height) * jy : float(c.height);
      }
      std::vector<Ray> batch(n + 1);
      batch[n].tmin = -7.0f;  // past the end: untouched
      cam.rays(px.data(), py.data(), n, batch.data());
      for (int i = 0; i < n; ++i) {
        const Ray one = cam.ray(px[i], py[i]);
        const Ray& b = batch[i];
        ASSERT_TRUE(same_bits(b.dir.x, one.dir.x) && same_bits(b.dir.y, one.dir.y) &&
                    same_bits(b.dir.z, one.dir.z))
            << "ray " << i << " of " << n << " at (" << px[i] << ", " << py[i] << ")";
        ASSERT_TRUE(b.org == one.org && b.tmin == one.tmin && b.tmax == one.tmax) << i;
      }
      EXPECT_EQ(batch[n].tmin, -7.0f);
    }
  }
}

TEST(CameraRays, BatchDirectionsAreUnitAndSpanTheFieldOfView) {
  const CameraRays cam(camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0f, 200, 100));
  const float px[] = {100, 0, 200, 100, 0}, py[] = {50, 50, 50, 0, 0};
  Ray r[5];
  cam.rays(px, py, 5, r);
  for (const Ray& ray : r) EXPECT_NEAR(length(ray.dir), 1.0f, 1e-6f);
  EXPECT_NEAR(r[0].dir.z, -1.0f, 1e-7f);
  // Half the height spans 45°, so the left edge (twice as far) is atan(2) off the axis.
  EXPECT_NEAR(r[1].dir.x / -r[1].dir.z, -2.0f, 1e-5f);
  EXPECT_NEAR(r[2].dir.x / -r[2].dir.z, 2.0f, 1e-5f);
  EXPECT_NEAR(r[3].dir.y / -r[3].dir.z, 1.0f, 1e-5f);
}

// The sample positions as first written: one function of (x, y, s, n).
std::pair<float, float> reference_position(int x, int y, int s, int n) {
  const auto hash32 = [](uint32_t v) {
    v ^= v >> 16;
    v *= 0x7feb352dU;
    v ^= v >> 15;
    v *= 0x846ca68bU;
    v ^= v >> 16;
    return v;
  };
  const auto unit = [](uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); };
  if (n <= 1) return {0.5f, 0.5f};
  const uint32_t seed = hash32(uint32_t(x) * 0x9e3779b9U ^ hash32(uint32_t(y) + 0x632be5abU));
  const float jx = unit(hash32(seed ^ uint32_t(2 * s))), jy = unit(hash32(seed ^ uint32_t(2 * s + 1)));
  const int k = static_cast<int>(std::lround(std::sqrt(double(n))));
  if (k * k == n) return {(float(s % k) + jx) / float(k), (float(s / k) + jy) / float(k)};
  const int row = int((uint32_t(s) + seed) % uint32_t(n));
  return {(float(s) + jx) / float(n), (float(row) + jy) / float(n)};
}

TEST(PixelSamples, PositionsFollowTheHashedStrata) {
  for (int n : {0, 1, 2, 3, 4, 5, 9, 16, 17, 64, 100}) {
    const PixelSamples samples(n);
    EXPECT_EQ(samples.count(), std::max(1, n));
    for (int y : {0, 3, 1079})
      for (int x : {0, 1, 7, 1919}) {
        const uint32_t seed = PixelSamples::seed(x, y);
        for (int s = 0; s < samples.count(); ++s) {
          const auto got = samples.position(seed, s), want = reference_position(x, y, s, n);
          ASSERT_TRUE(same_bits(got.first, want.first) && same_bits(got.second, want.second))
              << "n " << n << " pixel " << x << "," << y << " sample " << s;
          ASSERT_EQ(sample_position(x, y, s, n), got);
        }
      }
  }
}

}  // namespace
}  // namespace rayvec
