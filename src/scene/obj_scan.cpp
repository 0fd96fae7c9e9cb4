#include "scene/obj_scan.h"

#include <array>
#include <charconv>
#include <cstdlib>
#include <string>
#include <cmath>
#include <vector>

#include "io/csv_fields.h"
#include "geometry/coordinate_range.h"
#include "io/input_error.h"
#include "io/text_file.h"

namespace rayvec {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Splits off the next whitespace-separated token; empty at the end of the line.
std::string_view next_token(std::string_view& line) {
  std::size_t i = 0;
  while (i < line.size() && is_space(line[i])) ++i;
  std::size_t j = i;
  while (j < line.size() && !is_space(line[j])) ++j;
  const std::string_view token = line.substr(i, j - i);
  line.remove_prefix(j);
  return token;
}

// Coordinate k (0-based) of a `v`, `vn` or `vt` line must be a finite float (tinyobjloader stores
// floats); a `v` coordinate must also lie within the intersectors' range.
void check_coordinate(std::string_view token, int k, const char* kind, const std::string& path,
                      std::size_t line_no) {
  std::string_view digits = token;
  if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const bool parsed =
      end == digits.data() + digits.size() && (ec == std::errc() || ec == std::errc::result_out_of_range);
  // from_chars leaves `value` unchanged (0) when out of range: strtod tells 1e400 (inf,
  // rejected below) from 1e-400 (0, accepted).
  if (parsed && ec == std::errc::result_out_of_range)
    value = std::strtod(std::string(digits).c_str(), nullptr);
  if (!parsed || !std::isfinite(value) || !std::isfinite(static_cast<float>(value)))
    throw InputError(path, line_no,
                     std::string("`") + kind + "` coordinate " + std::to_string(k + 1) + " '" +
                         printable(token) + "' is not a finite number");
  if (kind[0] == 'v' && kind[1] == '\0' && !coordinate_in_range(static_cast<float>(value)))
    throw InputError(path, line_no,
                     "`v` coordinate " + std::to_string(k + 1) + " '" + printable(token) + "' is beyond " +
                         kCoordinateRangeText);
}

// `v`, `vn`, `vt`: the first `needed` numbers must be finite floats, and so must the next `optional`
// ones that are present (a `vt`'s second, which tinyobjloader reads when it is there), up to a `#`.
void check_coordinates(std::string_view rest, int needed, int optional, const char* kind,
                       const std::string& path, std::size_t line_no) {
  for (int k = 0; k < needed + optional; ++k) {
    const std::string_view token = next_token(rest);
    if (k >= needed && (token.empty() || token.front() == '#')) return;
    if (token.empty())
      throw InputError(path, line_no,
                       std::string("`") + kind + "` needs " + std::to_string(needed) +
                           " coordinates, found " + std::to_string(k));
    check_coordinate(token, k, kind, path, line_no);
  }
}

// Whether a token is a plain decimal: an optional sign, digits with at most one decimal point, and
// at least one digit (no exponent, no trailing characters).
bool is_plain_decimal(std::string_view token) {
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
  int digits = 0, points = 0;
  for (const char c : token) {
    if (c >= '0' && c <= '9')
      ++digits;
    else if (c == '.' && ++points == 1)
      continue;
    else
      return false;
  }
  return digits > 0;
}

// `vw vid joint weight joint weight ...` (tinyobjloader's skin-weight extension, unused by
// rayvec): tinyobjloader converts each joint id to int without a range check, which is undefined
// behaviour for NaN or ids of 2^31 and more (found by fuzz_obj). Its own number parser makes NaN of
// some forms that strtod reads as finite (a zero mantissa times an exponent of 10^1000000), so a
// joint id must be a plain decimal, whose value both read alike. Negative ids it rejects itself.
void check_skin_weights(std::string_view rest, const std::string& path, std::size_t line_no) {
  next_token(rest);  // vertex id
  for (int k = 0;; ++k) {
    const std::string_view token = next_token(rest);
    if (token.empty()) return;
    if (k % 2 != 0) continue;  // weights are floats, any value
    const double joint = is_plain_decimal(token) ? std::strtod(std::string(token).c_str(), nullptr) : NAN;
    if (!(joint < 2147483648.0))
      throw InputError(path, line_no,
                       "`vw` joint id '" + printable(token) +
                           "' is not a plain decimal number below 2^31 (digits, an optional sign "
                           "and decimal point)");
  }
}

// The colour of a `v` line (`v x y z r g b`), as tinyobjloader reads it: three tokens after the
// position that each start like a number (sign, digit or point), read as far as they look like one
// (`0.5x` is 0.5) and stored as floats. A component beyond float range (`1e39`, fifty digits) would
// be an infinite colour: an error, as for a coordinate. Tokens that do not start like numbers give
// no colour, and are not checked.
void check_vertex_colour(std::string_view rest, const std::string& path, std::size_t line_no) {
  for (int k = 0; k < 3; ++k) next_token(rest);  // the position, checked by check_coordinates
  std::array<std::string_view, 3> tokens;
  for (std::string_view& token : tokens) {
    token = next_token(rest);
    const char c = token.empty() ? '\0' : token.front();
    if (!(c == '+' || c == '-' || c == '.' || (c >= '0' && c <= '9'))) return;
  }
  for (int k = 0; k < 3; ++k) {
    const std::string text(tokens[k]);
    const float value = static_cast<float>(std::strtod(text.c_str(), nullptr));
    if (!std::isfinite(value))
      throw InputError(path, line_no,
                       "`v` colour component " + std::to_string(k + 1) + " '" + printable(tokens[k]) +
                           "' is not a finite number (colours are 0 to 1)");
  }
}

// Every number-like token of the lines tinyobjloader reads numbers from (v, vn, vt, vw, t) must
// have an exponent of at most kMaxExponentDigits digits (obj_scan.h says why).
void check_exponents(std::string_view rest, const std::string& path, std::size_t line_no) {
  for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest))
    if (exponent_too_long(token))
      throw InputError(path, line_no,
                       "number '" + printable(token) + "' has an exponent of more than " +
                           std::to_string(kMaxExponentDigits) +
                           " digits (a float needs at most 2: 3.4e38 to 1.4e-45)");
}

struct Counts {
  long v = 0, vt = 0, vn = 0;
};

// A positive index beyond what has been read so far may still be defined later in the file; those
// are checked once the totals are known.
struct ForwardRef {
  std::size_t line;
  long index;
  int kind;  // 0 v, 1 vt, 2 vn
};

const char* const kKindNames[] = {"vertex", "texture coordinate", "normal"};
const char* const kKindPlurals[] = {"vertices", "texture coordinates", "normals"};

// Returns the face's corner count.
long check_face(std::string_view rest, const Counts& seen, std::vector<ForwardRef>& forward,
                const std::string& path, std::size_t line_no) {
  long corners = 0;
  for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
    if (++corners > kMaxFaceCorners)
      throw InputError(path, line_no,
                       "a face with more than " + std::to_string(kMaxFaceCorners) +
                           " corners: rayvec does not triangulate polygons that large (the ear "
                           "clipping takes quadratic time); split it into smaller polygons");
    // v, v/vt, v//vn, v/vt/vn
    for (int kind = 0; kind < 3 && !token.empty(); ++kind) {
      const std::size_t slash = token.find('/');
      const std::string_view part = token.substr(0, slash);
      token = slash == std::string_view::npos ? std::string_view() : token.substr(slash + 1);
      if (part.empty() && kind > 0) continue;  // v//vn
      long index = 0;
      const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), index);
      const std::string where = std::string("face corner ") + std::to_string(corners) + ": " +
                                kKindNames[kind] + " index '" + printable(part) + "'";
      if (ec != std::errc() || end != part.data() + part.size())
        throw InputError(path, line_no, where + " is not an integer");
      if (index == 0) throw InputError(path, line_no, where + " is 0 (OBJ indices start at 1)");
      const long have = kind == 0 ? seen.v : kind == 1 ? seen.vt : seen.vn;
      if (index < 0 && have + index < 0)
        throw InputError(path, line_no,
                         where + " is out of range: only " + std::to_string(have) + " " + kKindPlurals[kind] +
                             " are defined before this line");
      if (index > have) forward.push_back({line_no, index, kind});
    }
  }
  if (corners < 3)
    throw InputError(path, line_no, "a face needs at least 3 corners, found " + std::to_string(corners));
  return corners;
}

}  // namespace

bool exponent_too_long(std::string_view token) {
  std::size_t i = 0;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  const std::size_t mantissa = i;
  while (i < token.size() && ((token[i] >= '0' && token[i] <= '9') || token[i] == '.')) ++i;
  if (i == mantissa || i >= token.size() || (token[i] != 'e' && token[i] != 'E')) return false;
  ++i;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  while (i < token.size() && token[i] == '0') ++i;
  std::size_t digits = 0;
  while (i + digits < token.size() && token[i + digits] >= '0' && token[i + digits] <= '9') ++digits;
  return digits > std::size_t(kMaxExponentDigits);
}

std::vector<LargeFace> check_obj_text(std::string_view text, const std::string& path) {
  Counts seen;
  std::vector<LargeFace> large;
  std::size_t faces = 0;
  std::vector<ForwardRef> forward;
  // Lines end as tinyobjloader ends them (LF, CRLF or a lone CR, as old Mac files have): with LF
  // only, a CR-only file would be one line here and its later lines would go unchecked.
  std::size_t pos = 0, line_no = 0;
  while (pos < text.size()) {
    std::string_view rest = next_text_line(text, pos);
    ++line_no;
    const std::string_view keyword = next_token(rest);
    const std::string_view numbers = rest;
    if (keyword == "v") {
      check_coordinates(rest, 3, 0, "v", path, line_no);
      check_vertex_colour(rest, path, line_no);
      ++seen.v;
    } else if (keyword == "vn") {
      check_coordinates(rest, 3, 0, "vn", path, line_no);
      ++seen.vn;
    } else if (keyword == "vt") {
      check_coordinates(rest, 1, 1, "vt", path, line_no);
      ++seen.vt;
    } else if (keyword == "f") {
      const long corners = check_face(rest, seen, forward, path, line_no);
      if (corners > kMaxTinyobjCorners) large.push_back({faces, static_cast<uint32_t>(corners)});
      ++faces;
    } else if (keyword == "vw") {
      check_skin_weights(rest, path, line_no);
    }
    // after the coordinates' own checks, so `1e400` is reported as not finite
    if (keyword == "v" || keyword == "vn" || keyword == "vt" || keyword == "vw" || keyword == "t")
      check_exponents(numbers, path, line_no);
  }
  for (const ForwardRef& ref : forward) {
    const long total = ref.kind == 0 ? seen.v : ref.kind == 1 ? seen.vt : seen.vn;
    if (ref.index > total)
      throw InputError(path, ref.line,
                       std::string("face ") + kKindNames[ref.kind] + " index " + std::to_string(ref.index) +
                           " is out of range: the file defines " + std::to_string(total) + " " +
                           kKindPlurals[ref.kind]);
  }
  return large;
}

}  // namespace rayvec
