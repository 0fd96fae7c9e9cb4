// parse_mtl: rayvec's reader of Wavefront MTL text, shared by every OBJ loader. It keeps the line of
// each value so that the checks applied after parsing (mtl_validate.h) and the texture look-up
// (texture_path.h) can name the MTL line a problem comes from. Values start at tinyobjloader's
// defaults (Kd 0, illum 0, Ns 1, Tf 0; Kd 0.6 when map_Kd is given without Kd), so a material
// looks the same whichever OBJ parser reads the faces.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "scene/material.h"

namespace rayvec {

// The line (1-based, 0 = not in the file) each key of one material was read from.
struct MtlLines {
  std::size_t newmtl = 0, Ka = 0, Kd = 0, Ks = 0, Ke = 0, Tf = 0, Ns = 0, Ni = 0, d = 0, illum = 0,
              map_Kd = 0;
};

struct MtlMaterial {
  Material material;  // map_Kd holds the name as written (options removed), not yet resolved
  MtlLines lines;
  std::string illum_text;  // the `illum` value as written when it is not an integer ("" otherwise)
};

// Reads `newmtl`, `Ka`, `Kd`, `Ks`, `Ke`, `Tf` (or `Kt`), `Ns`, `Ni`, `d`, `Tr` (d = 1 − Tr when no
// `d`), `illum` and `map_Kd` (its scale `-s u v w` and offset `-o u v w` kept, other texture options
// skipped; the rest of the line is the name, spaces included, surrounding quotes removed); other
// keys are ignored. A colour with one number is grey (g = b = r, as the MTL specification says).
// Materials come in file order; lines before the first `newmtl` are ignored. Throws InputError
// `path:line: ...` for a number that is not a finite float (`Kd 1e39`, `Ni nan`, `Ns x`).
std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& path);

}  // namespace rayvec
