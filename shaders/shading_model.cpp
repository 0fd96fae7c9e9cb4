#include "shaders/shading_model.h"

namespace rayvec::shaders {

ShadingModel shading_model(int illum) {
  switch (illum) {
    case 0: return ShadingModel::constant;
    case 1: return ShadingModel::diffuse;
    case 3:
    case 4: return ShadingModel::mirror;
    case 5: return ShadingModel::fresnel_mirror;
    case 6: return ShadingModel::glass;
    case 7: return ShadingModel::fresnel_glass;
    default: return illum < 0 ? ShadingModel::diffuse : ShadingModel::blinn_phong;  // 2, 8, 9, 10, > 10
  }
}

const char* shading_model_name(ShadingModel model) {
  switch (model) {
    case ShadingModel::constant: return "constant";
    case ShadingModel::diffuse: return "diffuse";
    case ShadingModel::blinn_phong: return "blinn_phong";
    case ShadingModel::mirror: return "mirror";
    case ShadingModel::fresnel_mirror: return "fresnel_mirror";
    case ShadingModel::glass: return "glass";
    case ShadingModel::fresnel_glass: return "fresnel_glass";
  }
  return "?";
}

bool is_lit(ShadingModel model) { return model != ShadingModel::constant; }

bool has_highlight(ShadingModel model) {
  return model != ShadingModel::constant && model != ShadingModel::diffuse;
}

bool reflects(ShadingModel model) {
  return model == ShadingModel::mirror || model == ShadingModel::fresnel_mirror || refracts(model);
}

bool refracts(ShadingModel model) {
  return model == ShadingModel::glass || model == ShadingModel::fresnel_glass;
}

bool uses_fresnel(ShadingModel model) {
  return model == ShadingModel::fresnel_mirror || model == ShadingModel::fresnel_glass;
}

bool reflects(const Material& m) { return reflects(shading_model(m)) && max_component(m.Ks) > 0; }
bool refracts(const Material& m) { return refracts(shading_model(m)) && max_component(m.Tf) > 0; }

Vec3f reflection_weight(const Material& m, float fresnel) { return m.Ks * fresnel; }

Vec3f transmission_weight(const Material& m, float fresnel) {
  return m.Tf * (uses_fresnel(m) ? 1.0f - fresnel : 1.0f);
}

}  // namespace rayvec::shaders
