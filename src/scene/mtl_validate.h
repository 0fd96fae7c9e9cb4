// validate_mtl_material: the ranges a scene JSON material must satisfy, applied to an MTL material
// after parsing (by any OBJ parser), so that no MTL value can turn into NaN or Inf in an image.
// Out-of-range values are warnings naming the MTL line, and the value is clamped into range:
// exporters write odd values (`Ni 0` for "unset", `Kd 1.02`), and a picture with a warning serves
// better than none. `render --strict` turns the warnings into errors.
#pragma once
#include <string>
#include <vector>

#include "scene/mtl_parser.h"

namespace rayvec {

// The ranges:
//   Ka, Kd, Ks, Tf   each component in [0, 1] (reflectances and a transmission filter)
//   Ke               each component in [0, kMaxEmission]
//   Ns               in [0, kMaxShininess] (the MTL specification's range is 0..1000)
//   d (and Tr)       in [0, 1]
//   Ni               in [kMinIor, kMaxIor] where the model reads it (illum 5, 6, 7); elsewhere any
//                    value is kept without a word, since exporters write `Ni 0` for "unset"
//   illum            an integer 0..10; anything else becomes 2 (Blinn–Phong)
// Each warning reads `path:line: material 'name': what; using what instead`.
inline constexpr float kMaxEmission = 1.0e6f;
inline constexpr float kMaxShininess = 1.0e4f;
inline constexpr float kMinIor = 1.0e-3f, kMaxIor = 10.0f;

void validate_mtl_material(MtlMaterial& m, const std::string& path, std::vector<std::string>& warnings);

}  // namespace rayvec
