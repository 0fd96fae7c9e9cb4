// Material: the MTL values rayvec reads (Wavefront MTL names), with the MTL defaults.
#pragma once
#include <array>
#include <string>

#include "math/vec3.h"

namespace rayvec {

struct Material {
  std::string name = "default";
  Vec3f Ka{0.0f, 0.0f, 0.0f};  // ambient reflectance (times the scene's ambient radiance)
  Vec3f Kd{0.8f, 0.8f, 0.8f};  // diffuse albedo (Lambertian BRDF Kd/pi)
  Vec3f Ks{0.0f, 0.0f, 0.0f};  // specular reflectance (Blinn–Phong highlight, mirror weight)
  Vec3f Ke{0.0f, 0.0f, 0.0f};  // emitted radiance
  Vec3f Tf{1.0f, 1.0f, 1.0f};  // transmission filter
  float Ns = 0.0f;             // Blinn–Phong exponent
  float Ni = 1.0f;             // index of refraction
  float d = 1.0f;              // dissolve (1 = opaque)
  int illum = 2;               // MTL illumination model 0..10
  std::string map_Kd;          // diffuse texture, absolute path ("" = none)
  // Where map_Kd is looked up: the texture coordinates (u, v) · scale + offset, the MTL options
  // `-s u v w` and `-o u v w` (w unused: textures are 2-D).
  std::array<float, 2> map_Kd_scale{1.0f, 1.0f}, map_Kd_offset{0.0f, 0.0f};
};

}  // namespace rayvec
