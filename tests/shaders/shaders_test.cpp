// The shading models against their textbook formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shaders/blinn_phong.h"
#include "shaders/dielectric.h"
#include "shaders/fresnel.h"
#include "shaders/lambert.h"
#include "shaders/mirror.h"

namespace rayvec::shaders {
namespace {

TEST(Shaders, LambertIsAlbedoOverPi) {
  const Vec3f l = lambert({0.5f, 1.0f, 0.0f}, {2.0f, 2.0f, 2.0f});
  EXPECT_FLOAT_EQ(l.x, 1.0f / std::numbers::pi_v<float>);
  EXPECT_FLOAT_EQ(l.z, 0.0f);
}

TEST(Shaders, FresnelAtNormalIncidenceAndTotalInternalReflection) {
  const float n = 1.5f, r0 = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f, n), r0, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(1.0f, n, 1.0f), r0, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(0.0f, 1.0f, n), 1.0f, 1e-6f);  // grazing
  EXPECT_EQ(fresnel_dielectric(0.5f, n, 1.0f), 1.0f);           // 60° inside glass: TIR
}

TEST(Shaders, RefractionObeysSnellAndReportsTotalInternalReflection) {
  const Vec3f n{0, 1, 0};
  const float a = 40.0f * std::numbers::pi_v<float> / 180.0f;
  const Vec3f d{std::sin(a), -std::cos(a), 0};
  const auto t = refract_direction(d, n, 1.0f / 1.5f);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->x, std::sin(a) / 1.5f, 1e-6f);  // sinθt = sinθi · n1/n2
  EXPECT_LT(t->y, 0.0f);
  const float b = 50.0f * std::numbers::pi_v<float> / 180.0f;
  EXPECT_FALSE(refract_direction({std::sin(b), -std::cos(b), 0}, n, 1.5f));  // sin 50° · 1.5 > 1
}

TEST(Shaders, MirrorAndHighlightPeakInTheMirrorDirection) {
  const Vec3f n{0, 0, 1};
  const Vec3f r = mirror_direction(normalize(Vec3f{1, 0, -1}), n);
  EXPECT_NEAR(r.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(r.z, std::sqrt(0.5f), 1e-6f);
  const Vec3f to_light = normalize(Vec3f{-1, 0, 1}), ks{1, 1, 1}, e{1, 1, 1};
  const float peak = blinn_phong(ks, 50, n, to_light, r, e).x;
  const float off = blinn_phong(ks, 50, n, to_light, normalize(Vec3f{1, 0.3f, 1}), e).x;
  EXPECT_NEAR(peak, 58.0f / (8.0f * std::numbers::pi_v<float>), 1e-4f);
  EXPECT_LT(off, peak);
  EXPECT_EQ(blinn_phong({0, 0, 0}, 50, n, to_light, r, e).x, 0.0f);
}

}  // namespace
}  // namespace rayvec::shaders
