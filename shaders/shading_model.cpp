#include "shaders/shading_model.h"

namespace rayvec::shaders {

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

}  // namespace rayvec::shaders
