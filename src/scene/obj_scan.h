// check_obj_text: rayvec's own pass over an OBJ file before tinyobjloader reads it, for what
// tinyobjloader does not report with a line number or at all: it reads `nan`/`inf` (and any other
// unparsable text) in a `v` line as 0.0, skips faces with out-of-range indices (quads) or keeps them
// (triangles) with only a global warning. One linear pass over the text; no allocation per line.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rayvec {

// Ear clipping (triangulate_polygon) takes up to quadratic time in a face's corners: a concave
// face of 10^4 corners takes a tenth of a second, so a single `f` line of 10^6 would hang the
// loader. Faces with more corners than this are rejected before either reader sees them.
inline constexpr long kMaxFaceCorners = 10000;

// tinyobjloader counts a face's corners in an unsigned char (num_face_vertices); a face with more
// than kMaxTinyobjCorners corners is listed with its true count, by its place among the file's
// `f` lines (0-based).
inline constexpr long kMaxTinyobjCorners = 255;
struct LargeFace {
  std::size_t face;
  uint32_t corners;
};

// The most digits the exponent of a number may have, leading zeros not counted, on the lines
// tinyobjloader reads numbers from (`v`, `vn`, `vt`, `vw`, `t`). Every float is written with two
// (3.4e38 … 1.4e-45). tinyobjloader computes m·5^e·2^e: from e = 442 on, 5^e is infinite and a zero
// mantissa makes NaN where the text means 0; at ten digits its int exponent overflows. Both
// readers refuse such numbers (the fast one by leaving the file to the reference path).
inline constexpr int kMaxExponentDigits = 2;

// Whether a number token (an optional sign, digits and point, then `e` or `E`, an optional sign
// and digits) has an exponent of more than kMaxExponentDigits digits, leading zeros not counted.
bool exponent_too_long(std::string_view token);

// Throws InputError `file:line: what is wrong` for: a `v`, `vn` or `vt` line with too few
// coordinates or a coordinate that is not a finite float (a `vt`'s optional second one too); a face
// (`f`) with fewer than 3 corners; a face index of 0, one that is not an integer, or one that refers to a
// vertex, normal or texture coordinate that does not exist (negative indices are relative, as in the OBJ
// specification); a face with more than kMaxFaceCorners corners; a number whose exponent has more than
// kMaxExponentDigits digits on a line tinyobjloader reads numbers from. Returns the faces of more
// than kMaxTinyobjCorners corners.
std::vector<LargeFace> check_obj_text(std::string_view text, const std::string& path);

}  // namespace rayvec
