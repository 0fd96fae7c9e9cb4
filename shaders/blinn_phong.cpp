#include "shaders/blinn_phong.h"

#include <cmath>
#include <numbers>

namespace rayvec::shaders {

Vec3f blinn_phong(Vec3f ks, float ns, Vec3f n, Vec3f to_light, Vec3f to_eye, Vec3f irradiance) {
  if (ks.x <= 0 && ks.y <= 0 && ks.z <= 0) return {};
  const Vec3f h = to_light + to_eye;
  const float len = length(h);
  if (!(len > 0)) return {};
  const float cos_h = dot(n, h) / len;
  if (!(cos_h > 0)) return {};
  const float norm = (ns + 8.0f) / (8.0f * std::numbers::pi_v<float>);  // energy normalisation
  const float lobe = norm * std::pow(cos_h, ns);
  return ks * irradiance * lobe;
}

}  // namespace rayvec::shaders
