// The material model: the MTL illum -> shading model mapping as shaders/shading_model.h documents it,
// and which models (and materials) spawn which rays.
#include <gtest/gtest.h>

#include <set>

#include "shaders/shading_model.h"

namespace rayvec::shaders {
namespace {

using M = ShadingModel;

const M kAllModels[] = {M::constant,       M::diffuse, M::blinn_phong,  M::mirror,
                        M::fresnel_mirror, M::glass,   M::fresnel_glass};

TEST(ShadingModel, EveryMtlIllumMapsAsDocumented) {
  const M expected[11] = {M::constant,        // 0: constant colour
                          M::diffuse,         // 1: ambient + diffuse
                          M::blinn_phong,     // 2: + highlight
                          M::mirror,          // 3: + ray-traced reflection
                          M::mirror,          // 4: MTL glass without refraction: a mirror
                          M::fresnel_mirror,  // 5: Fresnel-weighted reflection
                          M::glass,           // 6: reflection + refraction
                          M::fresnel_glass,   // 7: both Fresnel-weighted
                          M::blinn_phong,     // 8: reflection map (no ray tracing)
                          M::blinn_phong,     // 9: glass, reflection map (no ray tracing)
                          M::blinn_phong};    // 10: shadow matte
  for (int illum = 0; illum <= 10; ++illum)
    EXPECT_EQ(shading_model(illum), expected[illum])
        << "illum " << illum << " gave " << shading_model_name(shading_model(illum));
}

TEST(ShadingModel, IllumOutsideTheMtlRangeIsDiffuseBelowAndBlinnPhongAbove) {
  EXPECT_EQ(shading_model(-1), M::diffuse);
  EXPECT_EQ(shading_model(-100), M::diffuse);
  EXPECT_EQ(shading_model(11), M::blinn_phong);
  EXPECT_EQ(shading_model(1000), M::blinn_phong);
}

TEST(ShadingModel, MaterialModelIsItsIllumsModel) {
  Material m;
  EXPECT_EQ(shading_model(m), M::blinn_phong);  // the MTL default, illum 2
  for (int illum = -1; illum <= 11; ++illum) {
    m.illum = illum;
    EXPECT_EQ(shading_model(m), shading_model(illum)) << illum;
  }
}

TEST(ShadingModel, RaysSpawnExactlyForTheModelsThatTraceThem) {
  const std::set<M> reflecting{M::mirror, M::fresnel_mirror, M::glass, M::fresnel_glass};
  const std::set<M> refracting{M::glass, M::fresnel_glass};
  const std::set<M> fresnel{M::fresnel_mirror, M::fresnel_glass};
  for (M model : kAllModels) {
    SCOPED_TRACE(shading_model_name(model));
    EXPECT_EQ(reflects(model), reflecting.count(model) == 1);
    EXPECT_EQ(refracts(model), refracting.count(model) == 1);
    EXPECT_EQ(uses_fresnel(model), fresnel.count(model) == 1);
    EXPECT_EQ(is_lit(model), model != M::constant);
    EXPECT_EQ(has_highlight(model), model != M::constant && model != M::diffuse);
  }
}

TEST(ShadingModel, MaterialsSpawnRaysOnlyWithANonZeroWeight) {
  for (int illum = -1; illum <= 11; ++illum) {
    SCOPED_TRACE(illum);
    Material m;
    m.illum = illum;
    m.Ks = {0.5f, 0.0f, 0.0f};
    m.Tf = {0.0f, 0.0f, 0.25f};
    EXPECT_EQ(reflects(m), illum >= 3 && illum <= 7);
    EXPECT_EQ(refracts(m), illum == 6 || illum == 7);
    EXPECT_EQ(uses_fresnel(m), illum == 5 || illum == 7);
    m.Ks = {};
    m.Tf = {};
    EXPECT_FALSE(reflects(m));
    EXPECT_FALSE(refracts(m));
  }
}

TEST(ShadingModel, SecondaryRayWeights) {
  Material m;
  m.Ks = {0.5f, 0.25f, 1.0f};
  m.Tf = {1.0f, 0.5f, 0.0f};
  m.illum = 6;  // glass: Ks and Tf, no Fresnel (the integrator passes F = 1)
  EXPECT_EQ(reflection_weight(m, 1.0f).y, 0.25f);
  EXPECT_EQ(transmission_weight(m, 1.0f).y, 0.5f);
  m.illum = 7;  // fresnel_glass: Ks·F and Tf·(1 − F)
  EXPECT_EQ(reflection_weight(m, 0.25f).x, 0.125f);
  EXPECT_EQ(transmission_weight(m, 0.25f).x, 0.75f);
  EXPECT_EQ(transmission_weight(m, 0.25f).y, 0.375f);
}

}  // namespace
}  // namespace rayvec::shaders
