// bounce_directions is branch-free so that a generation's hits run in SIMD lanes; it must make the
// choices of the plain form with branches and optionals, written out here: the Fresnel term only
// for Fresnel models, the mirror about ng where ns bends it below the surface, and the
// refraction about ng where ns bends it back to the incoming side — but no fallback where the
// shading normal gives total internal reflection.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "render/bounce_directions.h"

namespace rayvec {
namespace {

struct Plain {
  Vec3f dir, mirror;
  float fresnel;
  std::optional<Vec3f> refracted;
};

Plain plain_bounce(Vec3f ray_dir, Vec3f ns, Vec3f ng, bool entering, float ni, bool fresnel_model) {
  Plain p;
  p.dir = normalize(ray_dir);
  const float n1 = entering ? 1.0f : ni, n2 = entering ? ni : 1.0f;
  p.fresnel = fresnel_model ? shaders::fresnel_dielectric(-dot(p.dir, ns), n1, n2) : 1.0f;
  p.mirror = shaders::mirror_direction(p.dir, ns);
  if (!(dot(p.mirror, ng) > 0)) p.mirror = shaders::mirror_direction(p.dir, ng);
  p.refracted = shaders::refract_direction(p.dir, ns, n1 / n2);
  if (p.refracted && !(dot(*p.refracted, ng) < 0))
    p.refracted = shaders::refract_direction(p.dir, ng, n1 / n2);
  return p;
}

bool same_bits(Vec3f a, Vec3f b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

TEST(BounceDirections, MakeThePlainFormsChoicesBitForBit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int tir = 0, mirror_bent = 0, refraction_bent = 0, refracted = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec3f ng = normalize(Vec3f{u(rng), u(rng), u(rng)});
    // shading normals near ng, some bent far enough to flip a child to the wrong side
    const Vec3f ns = normalize(ng + Vec3f{u(rng), u(rng), u(rng)} * (i % 3 == 0 ? 1.5f : 0.2f));
    Vec3f d{u(rng), u(rng), u(rng)};
    if (dot(d, ng) > 0) d = -d;                          // toward the surface
    if (i % 7 == 0) d = d - ng * (dot(d, ng) * 0.999f);  // grazing
    const bool entering = i % 2 == 0, fresnel_model = i % 5 != 0;
    const float ni = 1.0f + 1.5f * (u(rng) + 1.0f) / 2.0f;
    const BounceDirections got = bounce_directions(d, ns, ng, entering, ni, fresnel_model);
    const Plain want = plain_bounce(d, ns, ng, entering, ni, fresnel_model);
    ASSERT_TRUE(same_bits(got.dir, want.dir)) << i;
    ASSERT_EQ(got.fresnel, want.fresnel) << i;
    ASSERT_TRUE(same_bits(got.mirror, want.mirror)) << i;
    ASSERT_EQ(got.refracts, want.refracted.has_value()) << i;
    if (want.refracted) {
      ASSERT_TRUE(same_bits(got.refracted, *want.refracted)) << i;
    }
    tir += !want.refracted;
    refracted += want.refracted.has_value();
    mirror_bent += !(dot(shaders::mirror_direction(want.dir, ns), ng) > 0);
    const auto t = shaders::refract_direction(want.dir, ns, entering ? 1.0f / ni : ni);
    refraction_bent += t && !(dot(*t, ng) < 0);
  }
  // every branch of the plain form taken many times
  EXPECT_GT(tir, 1000);
  EXPECT_GT(refracted, 1000);
  EXPECT_GT(mirror_bent, 1000);
  EXPECT_GT(refraction_bent, 1000);
}

// Total internal reflection under the shading normal stays total even where the geometric
// normal would let the ray through: the fallback is only for a refraction that exists.
TEST(BounceDirections, NoRefractionFallbackUnderTotalInternalReflection) {
  const Vec3f ng{0, 1, 0};
  const Vec3f ns = normalize(Vec3f{0.5f, 0.866f, 0});      // tilted 30 degrees
  const Vec3f d = normalize(Vec3f{0.5736f, -0.8192f, 0});  // inside glass: 35 degrees from -ng, 65 from -ns
  const float ni = 1.5f;
  ASSERT_FALSE(shaders::refract_direction(d, ns, ni));             // beyond the critical angle (41.8 degrees)
  ASSERT_TRUE(shaders::refract_direction(d, ng, ni).has_value());  // not about ng
  const BounceDirections b = bounce_directions(d, ns, ng, false, ni, true);
  EXPECT_FALSE(b.refracts);
  EXPECT_EQ(b.fresnel, 1.0f);
}

}  // namespace
}  // namespace rayvec
