// The renderer against closed-form radiance: Lambertian Kd/π under a point light (I·cosθ/r²) and a
// directional light (E·cosθ), the camera's orientation conventions, and the effects plan.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <omp.h>

#include "accel/accelerator.h"
#include "render/camera_rays.h"
#include "render/effects.h"
#include "render/pixel_samples.h"
#include "render/renderer.h"
#include "render_test_scenes.h"

namespace rayvec {
namespace {

// Where the camera ray through pixel (x, y)'s centre meets the plane y = 0.
Vec3f plane_point(const Scene& s, int x, int y) {
  const Ray r = CameraRays(s.camera).ray(float(x) + 0.5f, float(y) + 0.5f);
  const float t = -r.org.y / r.dir.y;
  return r.org + r.dir * t;
}

Image render_scene(const Scene& s, RenderStats& stats, RenderSettings o = {}) {
  const auto accel = make_accelerator(AccelKind::brute, s.mesh, TraceConfig{});
  return render(s, *accel, o, stats);
}

TEST(Whitted, LambertPlaneUnderPointLightMatchesInverseSquareLaw) {
  const Vec3f kd{0.5f, 0.25f, 0.8f};
  Scene s = test::lambert_plane_scene(kd);
  const Vec3f light_pos{1.0f, 2.0f, -0.5f};
  const Vec3f intensity{10.0f, 20.0f, 5.0f};
  s.lights.push_back(Light{Light::Type::point, light_pos, {}, intensity});
  RenderStats stats;
  const Image img = render_scene(s, stats);
  for (auto [x, y] : {std::pair{32, 24}, {5, 5}, {60, 40}, {10, 44}, {50, 3}}) {
    const Vec3f p = plane_point(s, x, y);
    const Vec3f d = light_pos - p;
    const float r2 = dot(d, d), cos_theta = d.y / std::sqrt(r2);
    for (int c = 0; c < 3; ++c) {
      const float expected = kd[c] / std::numbers::pi_v<float> * intensity[c] * cos_theta / r2;
      EXPECT_NEAR(img.at(x, y, c), expected, 0.01f * expected) << x << "," << y << " c" << c;
    }
  }
  EXPECT_EQ(stats.rays.primary, 64u * 48u);
  EXPECT_EQ(stats.rays.primary_hits, 64u * 48u);  // the plane fills the image
  EXPECT_EQ(stats.rays.shadow, 64u * 48u);
  EXPECT_EQ(stats.rays.reflection, 0u);
  EXPECT_EQ(stats.rays.refraction, 0u);
}

TEST(Whitted, LambertPlaneUnderDirectionalLightIsIrradianceTimesCosine) {
  Scene s = test::lambert_plane_scene({0.6f, 0.6f, 0.6f});
  const Vec3f travel = normalize(Vec3f{1.0f, -2.0f, 0.5f});  // the way the light travels
  s.lights.push_back(Light{Light::Type::directional, {}, travel, {3.0f, 3.0f, 3.0f}});
  RenderStats stats;
  const Image img = render_scene(s, stats);
  const float expected = 0.6f / std::numbers::pi_v<float> * 3.0f * -travel.y;
  for (auto [x, y] : {std::pair{32, 24}, {0, 0}, {63, 47}})
    EXPECT_NEAR(img.at(x, y, 1), expected, 0.01f * expected) << x << "," << y;
}

TEST(Whitted, LightBelowThePlaneCastsNoShadowRays) {
  Scene s = test::lambert_plane_scene({0.5f, 0.5f, 0.5f});
  s.lights.push_back(Light{Light::Type::point, {0, -1, 0}, {}, {1, 1, 1}});
  RenderStats stats;
  const Image img = render_scene(s, stats);
  EXPECT_EQ(stats.rays.shadow, 0u);
  EXPECT_EQ(img.at(32, 24, 0), 0.0f);
}

TEST(Whitted, OccluderCastsShadow) {
  Scene s = test::lambert_plane_scene({0.5f, 0.5f, 0.5f});
  Material m;
  const int32_t mat = s.add_material(m);
  // A small triangle halfway between the light and the plane's centre, off the camera's view ray.
  s.lights.push_back(Light{Light::Type::point, {3, 2, 0}, {}, {10, 10, 10}});
  s.add_triangle({1.4f, 1, -0.2f}, {1.6f, 1, -0.2f}, {1.5f, 1, 0.3f}, mat);
  RenderStats stats;
  const Image img = render_scene(s, stats);
  // The centre pixel sees the plane at the origin; the path to the light passes (1.5, 1, 0).
  EXPECT_EQ(img.at(32, 24, 0), 0.0f);
  EXPECT_GT(img.at(32, 20, 0), 0.0f);
}

TEST(Whitted, CameraRightIsForwardCrossUpAndRowZeroIsTop) {
  Camera c;
  c.eye = {0, 0, 0};
  c.look_at = {0, 0, -1};
  c.up = {0, 1, 0};
  c.width = 40;
  c.height = 30;
  const CameraRays cam(c);
  EXPECT_GT(cam.ray(39.5f, 15.0f).dir.x, 0.0f);  // right edge looks toward +x = cross(-z, +y)
  EXPECT_GT(cam.ray(20.0f, 0.5f).dir.y, 0.0f);   // row 0 looks up
  const Ray centre = cam.ray(20.0f, 15.0f);
  EXPECT_NEAR(centre.dir.z, -1.0f, 1e-6f);
  // fov_y spans the height: the top edge is 22.5° above the axis for fov_y = 45.
  const Ray top = cam.ray(20.0f, 0.0f);
  EXPECT_NEAR(std::atan2(top.dir.y, -top.dir.z), 22.5 * std::numbers::pi / 180.0, 1e-5);
}

TEST(Whitted, EffectsPlanNamesOnlyWhatTheSceneNeeds) {
  Scene s = test::lambert_plane_scene({0.5f, 0.5f, 0.5f});
  EXPECT_EQ(plan_effects(s).describe(), "effects: shadows: none, reflection: none, refraction: none");
  s.lights.push_back(Light{});
  s.lights.push_back(Light{});
  Material mirror;
  mirror.illum = 3;
  mirror.Ks = {0.9f, 0.9f, 0.9f};
  Material glass;
  glass.illum = 7;
  glass.Ks = {1, 1, 1};
  Material unused = glass;
  s.add_triangle({0, 1, 0}, {1, 1, 0}, {0, 1, 1}, s.add_material(mirror));
  s.add_triangle({0, 2, 0}, {1, 2, 0}, {0, 2, 1}, s.add_material(glass));
  s.add_material(unused);
  EXPECT_EQ(plan_effects(s).describe(),
            "effects: shadows (2 lights), reflection (2 materials), refraction (1 material)");
}

TEST(Whitted, MirrorShowsTheBackgroundAndCountsReflectionRays) {
  // No lights: the floor is black and the mirror facing the camera shows Ks·background.
  Scene s = test::lambert_plane_scene({0.5f, 0.5f, 0.5f});
  s.background = {0.2f, 0.4f, 0.6f};
  Material mirror;
  mirror.illum = 3;
  mirror.Kd = {0, 0, 0};
  mirror.Ks = {0.5f, 0.5f, 0.5f};
  const int32_t mat = s.add_material(mirror);
  s.add_triangle({-1, 2, -1}, {0, 2, 1}, {1, 2, -1}, mat);  // horizontal, facing +y
  RenderStats stats;
  Image img = render_scene(s, stats);
  EXPECT_GT(stats.rays.reflection, 0u);
  EXPECT_LT(stats.rays.reflection, stats.rays.primary);
  EXPECT_EQ(stats.rays.refraction, 0u);
  EXPECT_NEAR(img.at(32, 24, 0), 0.1f, 1e-6f);
  EXPECT_NEAR(img.at(32, 24, 2), 0.3f, 1e-6f);
  EXPECT_EQ(img.at(2, 2, 0), 0.0f);

  // Adaptive depth: a child weighing less than min_contribution is never traced, and
  // max_depth = 0 allows no children at all.
  s.materials[mat].Ks = {0.005f, 0.005f, 0.005f};
  render_scene(s, stats);
  EXPECT_EQ(stats.rays.reflection, 0u);
  s.materials[mat].Ks = {0.5f, 0.5f, 0.5f};
  RenderSettings shallow;
  shallow.max_depth = 0;
  img = render_scene(s, stats, shallow);
  EXPECT_EQ(stats.rays.reflection, 0u);
  EXPECT_EQ(img.at(32, 24, 0), 0.0f);
}

TEST(Whitted, IndexMatchedGlassTransmitsTheBackgroundFilteredByTf) {
  Scene s = test::lambert_plane_scene({0.5f, 0.5f, 0.5f});
  s.background = {1.0f, 1.0f, 1.0f};
  s.mesh = {};
  s.triangle_material.clear();
  s.triangle_object.clear();
  s.normal_corners.clear();
  s.uv_corners.clear();
  s.normal_table.clear();
  s.uv_table.clear();
  Material glass;
  glass.illum = 6;
  glass.Kd = {0, 0, 0};
  glass.Ni = 1.0f;
  glass.Tf = {0.9f, 0.5f, 0.1f};
  s.add_triangle({-100, 0, 100}, {100, 0, 100}, {0, 0, -100}, s.add_material(glass));
  RenderStats stats;
  const Image img = render_scene(s, stats);
  EXPECT_EQ(stats.rays.refraction, stats.rays.primary);
  EXPECT_EQ(stats.rays.reflection, 0u);
  EXPECT_NEAR(img.at(10, 10, 0), 0.9f, 1e-6f);
  EXPECT_NEAR(img.at(10, 10, 1), 0.5f, 1e-6f);
}

TEST(Whitted, SupersamplingIsIndependentOfThreadCount) {
  Scene s = test::lambert_plane_scene({0.5f, 0.5f, 0.5f});
  s.lights.push_back(Light{Light::Type::point, {0, 2, 0}, {}, {5, 5, 5}});
  RenderSettings o;
  o.spp = 5;
  RenderStats a, b;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Image one = render_scene(s, a, o);
  omp_set_num_threads(2);
  const Image two = render_scene(s, b, o);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.pixels, two.pixels);
  EXPECT_EQ(a.rays.primary, 5u * 64u * 48u);
}

TEST(Whitted, StratifiedSamplesCoverEveryStratum) {
  for (int n : {4, 9, 5}) {
    std::vector<int> cols(n, 0), rows(n, 0);
    for (int s = 0; s < n; ++s) {
      const auto [sx, sy] = sample_position(7, 3, s, n);
      ASSERT_TRUE(sx >= 0 && sx < 1 && sy >= 0 && sy < 1);
      if (n == 5) {
        ++cols[int(sx * n)];
        ++rows[int(sy * n)];
      }
    }
    if (n == 5) {
      for (int i = 0; i < n; ++i) EXPECT_TRUE(cols[i] == 1 && rows[i] == 1) << i;
    }
  }
  EXPECT_EQ(sample_position(1, 2, 0, 1), (std::pair{0.5f, 0.5f}));
}

}  // namespace
}  // namespace rayvec
