// The ray tree of `rayvec trace` (render/ray_tree.h): it is what made the pixel (its pixel value
// equals the rendered image's, its rays' contributions add up to the sample's radiance), and it
// names every ray kind and every reason a ray stops, on scenes built so that each reason occurs.
#include <gtest/gtest.h>

#include <functional>

#include "accel/accelerator.h"
#include "render/ray_tree.h"
#include "render/ray_tree_format.h"
#include "render/renderer.h"

namespace rayvec {
namespace {

// A glass plane y = 0 whose front faces down, seen from above at 63° from its normal: the camera
// ray meets it from the back, inside the glass, beyond the critical angle (41.8° for Ni 1.5).
Scene glass_from_inside_scene() {
  Scene s;
  Material glass;
  glass.name = "glass";
  glass.Ka = glass.Kd = {0, 0, 0};
  glass.Ks = {1, 1, 1};
  glass.Ns = 300;
  glass.Ni = 1.5f;
  glass.illum = 7;
  const int32_t m = s.add_material(glass);
  s.add_triangle({-100, 0, 100}, {0, 0, -100}, {100, 0, 100}, m);
  s.camera.eye = {0, 1, 2};
  s.camera.look_at = {0, 0, 0};
  s.camera.width = 32;
  s.camera.height = 24;
  s.background = {0.2f, 0.4f, 0.8f};
  return s;
}

// A Lambertian floor lit from straight above, a small roof between the light and the floor's
// centre, the camera looking at that centre from the side (past the roof).
Scene blocked_light_scene() {
  Scene s;
  Material floor;
  floor.name = "floor";
  floor.illum = 1;
  const int32_t m = s.add_material(floor);
  s.add_triangle({-10, 0, 10}, {10, 0, 10}, {0, 0, -10}, m);
  s.add_triangle({-0.5f, 2, 0.5f}, {0.5f, 2, 0.5f}, {0, 2, -0.5f}, m);
  s.lights.push_back(Light{Light::Type::point, {0, 5, 0}, {}, {10, 10, 10}});
  s.camera.eye = {0, 3, 3};
  s.camera.look_at = {0, 0, 0};
  s.camera.width = 32;
  s.camera.height = 24;
  return s;
}

const RayNode* find(const RayNode& n, const std::function<bool(const RayNode&)>& pred) {
  if (pred(n)) return &n;
  for (const RayNode& c : n.children)
    if (const RayNode* r = find(c, pred)) return r;
  return nullptr;
}

bool has_skip(const RayNode& n, SkipReason reason) {
  for (const SkippedRay& s : n.skipped)
    if (s.reason == reason) return true;
  return false;
}

Vec3f summed_contributions(const RayNode& n) {
  Vec3f sum = n.kind == RayKind::shadow ? Vec3f{} : n.contribution();
  for (const RayNode& c : n.children) sum += summed_contributions(c);
  return sum;
}

TEST(RayTree, TotalInternalReflectionIsNamedAndTheReflectionCarriesIt) {
  const Scene s = glass_from_inside_scene();
  const auto accel = make_accelerator(AccelKind::bvh, s.mesh, TraceConfig{});
  const PixelTrace t = trace_pixel(s, *accel, s.render, 16, 12, 0);
  ASSERT_TRUE(t.root.hit.hit());
  EXPECT_TRUE(has_skip(t.root, SkipReason::total_internal_reflection));
  ASSERT_EQ(t.root.children.size(), 1u);
  const RayNode& r = t.root.children[0];
  EXPECT_EQ(r.kind, RayKind::reflection);
  EXPECT_FLOAT_EQ(r.weight, 1.0f);  // Fresnel reflectance is 1 beyond the critical angle
  EXPECT_FALSE(r.hit.hit());
  EXPECT_EQ(r.stop_reasons(s), std::vector<std::string>{"miss"});
  const std::string text = ray_tree_text(t, s);
  EXPECT_NE(text.find("refraction ray not traced: total internal reflection"), std::string::npos) << text;
  EXPECT_NE(ray_tree_json(t, s).find("\"reason\": \"total_internal_reflection\""), std::string::npos);
}

TEST(RayTree, MaxDepthZeroStopsBothChildren) {
  Scene s = glass_from_inside_scene();
  s.render.max_depth = 0;
  const auto accel = make_accelerator(AccelKind::bvh, s.mesh, TraceConfig{});
  const PixelTrace t = trace_pixel(s, *accel, s.render, 16, 12, 0);
  EXPECT_TRUE(t.root.children.empty());
  ASSERT_EQ(t.root.skipped.size(), 2u);
  EXPECT_EQ(t.root.skipped[0].reason, SkipReason::max_depth);
  EXPECT_EQ(t.root.skipped[1].reason, SkipReason::max_depth);
  const std::vector<std::string> why = t.root.stop_reasons(s);
  EXPECT_EQ(why, (std::vector<std::string>{"max_depth", "max_depth"}));
}

TEST(RayTree, ShadowRayToABlockedLightNamesTheBlocker) {
  const Scene s = blocked_light_scene();
  const auto accel = make_accelerator(AccelKind::bvh, s.mesh, TraceConfig{});
  const PixelTrace t = trace_pixel(s, *accel, s.render, 16, 12, 0);
  EXPECT_EQ(t.root.hit.tri, 0);
  ASSERT_EQ(t.root.children.size(), 1u);
  const RayNode& sh = t.root.children[0];
  EXPECT_EQ(sh.kind, RayKind::shadow);
  EXPECT_TRUE(sh.blocked);
  EXPECT_EQ(sh.hit.tri, 1);  // the roof
  EXPECT_EQ(sh.stop_reasons(s), std::vector<std::string>{"light_blocked"});
  EXPECT_EQ(t.root.stop_reasons(s), std::vector<std::string>{"diffuse"});
  EXPECT_EQ(t.pixel.x, 0.0f);  // ambient 0, the only light blocked
  // a pixel near the image edge sees the lit floor: the light is reached and adds what it lights
  const PixelTrace lit = trace_pixel(s, *accel, s.render, 2, 20, 0);
  ASSERT_EQ(lit.root.children.size(), 1u);
  EXPECT_FALSE(lit.root.children[0].blocked);
  EXPECT_GT(lit.root.children[0].lit.x, 0.0f);
  EXPECT_EQ(lit.root.children[0].lit.x, lit.pixel.x);
}

TEST(RayTree, EffectsOffAreNamedAndLightsThenReachEverything) {
  Scene s = blocked_light_scene();
  s.render.effects.shadows = false;
  const auto accel = make_accelerator(AccelKind::bvh, s.mesh, TraceConfig{});
  const PixelTrace t = trace_pixel(s, *accel, s.render, 16, 12, 0);
  EXPECT_TRUE(t.root.children.empty());  // no shadow ray
  EXPECT_GT(t.pixel.x, 0.0f);            // and the roof no longer shadows the floor
  Scene g = glass_from_inside_scene();
  g.render.effects.reflection = false;
  const auto accel2 = make_accelerator(AccelKind::bvh, g.mesh, TraceConfig{});
  const PixelTrace tg = trace_pixel(g, *accel2, g.render, 16, 12, 0);
  EXPECT_TRUE(has_skip(tg.root, SkipReason::effect_off));
}

// The default scene: every traced pixel's value equals the rendered image's exactly (the same
// arithmetic), its rays' contributions add up to the sample's radiance, and among them are
// camera, shadow, reflection and refraction rays, misses, cutoffs and max-depth stops.
TEST(RayTree, PixelValueEqualsTheRenderedImage) {
  Scene s = load_scene(std::string(RAYVEC_SOURCE_DIR) + "/scenes/whitted.json");
  s.camera.width = 64;
  s.camera.height = 48;
  s.render.spp = 2;
  s.render.max_depth = 3;
  const auto accel = make_accelerator(AccelKind::bvh, s.mesh, TraceConfig{});
  RenderStats stats;
  const Image img = render(s, *accel, s.render, stats);
  bool kinds[4] = {}, miss = false, cutoff = false, max_depth = false;
  for (int y = 1; y < 48; y += 3)
    for (int x = 2; x < 64; x += 3) {
      const PixelTrace t = trace_pixel(s, *accel, s.render, x, y, (x + y) % 2);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(t.pixel[c], img.at(x, y, c)) << x << "," << y;
      const Vec3f sum = summed_contributions(t.root);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sum[c], t.sample_radiance[c], 1e-5f + 1e-5f * t.sample_radiance[c]);
      for (int k = 0; k < 4; ++k)
        kinds[k] |= find(t.root, [k](const RayNode& n) { return int(n.kind) == k; }) != nullptr;
      miss |=
          find(t.root, [](const RayNode& n) { return n.kind != RayKind::shadow && !n.hit.hit(); }) != nullptr;
      cutoff |= find(t.root, [](const RayNode& n) { return has_skip(n, SkipReason::contribution_cutoff); }) !=
                nullptr;
      max_depth |=
          find(t.root, [](const RayNode& n) { return has_skip(n, SkipReason::max_depth); }) != nullptr;
    }
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(kinds[k]) << ray_kind_name(RayKind(k));
  EXPECT_TRUE(miss);
  EXPECT_TRUE(cutoff);
  EXPECT_TRUE(max_depth);
}

TEST(RayTree, ObserverDoesNotChangeTheImageAndCostAovsArePlausible) {
  Scene s = load_scene(std::string(RAYVEC_SOURCE_DIR) + "/scenes/whitted.json");
  s.camera.width = 48;
  s.camera.height = 36;
  s.render.spp = 1;
  const auto accel = make_accelerator(AccelKind::bvh, s.mesh, TraceConfig{});
  RenderStats stats;
  const Image plain = render(s, *accel, s.render, stats);
  RenderSettings with = s.render;
  with.aov.cost = with.aov.bounces = true;
  const Image counted = render(s, *accel, with, stats);
  ASSERT_EQ(counted.channels,
            (std::vector<std::string>{"R", "G", "B", "cost.nodes", "cost.triangles", "bounces"}));
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 48; ++x) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(plain.at(x, y, c), counted.at(x, y, c));
      // the cost AOV sums the per-ray counts the tree shows
      if (x % 7 || y % 5) continue;
      const PixelTrace t = trace_pixel(s, *accel, s.render, x, y, 0);
      TraversalCost sum;
      std::function<void(const RayNode&)> add = [&](const RayNode& n) {
        sum += n.cost;
        for (const RayNode& c : n.children) add(c);
      };
      add(t.root);
      EXPECT_EQ(float(sum.nodes), counted.at(x, y, 3)) << x << "," << y;
      EXPECT_EQ(float(sum.triangles), counted.at(x, y, 4)) << x << "," << y;
    }
}

}  // namespace
}  // namespace rayvec
