#include "shaders/lambert.h"

#include <numbers>

namespace rayvec::shaders {

Vec3f lambert(Vec3f kd, Vec3f irradiance) { return kd * irradiance * std::numbers::inv_pi_v<float>; }

}  // namespace rayvec::shaders
