// check_obj_text: rayvec's own pass over an OBJ file before tinyobjloader reads it, for what
// tinyobjloader does not report with a line number or at all: it reads `nan`/`inf` (and any other
// unparsable text) in a `v` line as 0.0, skips faces with out-of-range indices (quads) or keeps them
// (triangles) with only a global warning. One linear pass over the text; no allocation per line.
#pragma once
#include <string>
#include <string_view>

namespace rayvec {

// tinyobjloader triangulates a polygon by ear clipping in worse than quadratic time: 10^4 corners
// take 0.3 s, 10^5 corners 40 s, so a single `f` line of 10^6 corners would hang the loader.
// Faces with more corners than this are rejected before tinyobjloader sees them.
inline constexpr long kMaxFaceCorners = 10000;

// Throws InputError `file:line: what is wrong` for: a `v`, `vn` or `vt` line with too few
// coordinates or a coordinate that is not a finite float; a face (`f`) with fewer than 3 corners; a
// face index of 0, one that is not an integer, or one that refers to a vertex, normal or texture
// coordinate that does not exist (negative indices are relative, as in the OBJ specification); a
// face with more than kMaxFaceCorners corners.
void check_obj_text(std::string_view text, const std::string& path);

}  // namespace rayvec
