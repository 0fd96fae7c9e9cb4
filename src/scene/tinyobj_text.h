// text_for_tinyobjloader: the OBJ text the reference path hands tinyobjloader, rewritten where
// tinyobjloader's own reading would differ from rayvec's (material_names.h) or refuse what rayvec
// does not draw. The fast reader reads the original text the same way.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "scene/material_names.h"

namespace rayvec {

// `text` (an OBJ file) as tinyobjloader is to read it: the name of every `usemtl` line written as
// its material_key, every `mtllib` line's rest through mtllib_text, and `l` (line) and `p` (point)
// lines emptied — rayvec draws neither, and tinyobjloader refuses the whole file for one it cannot
// read (`l 1 2 # edge`: the comment as index 0); line ends and everything else unchanged.
// `usemtl_lines` receives the file's `usemtl` lines in order.
std::string text_for_tinyobjloader(std::string_view text, std::vector<UsemtlLine>& usemtl_lines,
                                   const MtlFileExists& exists);

}  // namespace rayvec
