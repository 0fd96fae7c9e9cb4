// read_mtl_file: one MTL file, from path to ready materials, for any OBJ parser. Read within the
// input limit and NUL check every input has (read_text_file), parsed (mtl_parser.h), validated
// (mtl_validate.h), and each map_Kd resolved and checked (texture_path.h).
#pragma once
#include <string>
#include <vector>

#include "scene/material.h"

namespace rayvec {

// The materials of the MTL file at `path`, in file order, map_Kd absolute (or "" when the texture
// cannot be used: a warning `path:line: material 'name': texture '...' not found; drawn with Kd
// only` then says why). Out-of-range values are clamped with a warning. Throws InputError for a
// file that cannot be read, is binary, exceeds the input limit or holds a number that is not finite.
std::vector<Material> read_mtl_file(const std::string& path, std::vector<std::string>& warnings);

}  // namespace rayvec
