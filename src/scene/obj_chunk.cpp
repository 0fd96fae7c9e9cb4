// The only file that includes fast_float (Debian's libfast-float-dev, header only): correctly
// rounded decimal-to-double conversion, the same value std::from_chars gives obj_scan.cpp's check.
// tinyobjloader's own conversion accumulates digits in double arithmetic, so its floats can differ
// from these in the last bit (see benchmarks.md#decision-obj-fast-path).
#include "scene/obj_chunk.h"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <cmath>
#include <system_error>

#include "geometry/coordinate_range.h"
#include "scene/material_names.h"
#include "scene/obj_scan.h"

namespace rayvec {
namespace {

constexpr int kV = 0, kVt = 1, kVn = 2;  // the order of `a/b/c` in a face corner

bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_line_end(char c) { return c == '\n' || c == '\r'; }
bool is_digit(char c) { return static_cast<unsigned>(c - '0') < 10u; }

// Clinger's fast path (Clinger 1990): a decimal of at most 15 digits and no exponent is m / 10^k
// with m and 10^k exact doubles, so one IEEE division rounds it correctly, the value fast_float
// gives. Returns the end of the number, or nullptr when the text needs fast_float.
const char* short_decimal(const char* p, const char* end, double& value) {
  static constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  const bool negative = p != end && *p == '-';
  p += negative;
  uint64_t m = 0;
  int digits = 0, fraction = 0;
  for (; p != end && is_digit(*p); ++p, ++digits) m = m * 10 + static_cast<uint64_t>(*p - '0');
  if (p != end && *p == '.')
    for (++p; p != end && is_digit(*p); ++p, ++digits, ++fraction)
      m = m * 10 + static_cast<uint64_t>(*p - '0');
  if (digits == 0 || digits > 15 || (p != end && (*p == 'e' || *p == 'E'))) return nullptr;
  value = static_cast<double>(m) / kPow10[fraction];
  if (negative) value = -value;
  return p;
}

class Cursor {
 public:
  Cursor(const char* p, const char* end) : p_(p), end_(end) {}

  bool done() const { return p_ == end_; }
  const char* pos() const { return p_; }
  bool at_line_end() const { return p_ == end_ || is_line_end(*p_); }
  bool at_token_end() const { return p_ == end_ || is_blank(*p_) || is_line_end(*p_); }
  char peek(std::ptrdiff_t ahead = 0) const { return end_ - p_ > ahead ? p_[ahead] : '\0'; }
  void skip_blanks() {
    while (p_ != end_ && is_blank(*p_)) ++p_;
  }
  std::string_view token() {
    const char* start = p_;
    while (!at_token_end()) ++p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }
  void jump(const char* p) { p_ = p; }

  // Moves past the line end. False for a lone CR inside the text: tinyobjloader ends a line there
  // too, but the chunking (split at LF) and this parser do not follow it.
  bool next_line() {
    while (p_ != end_ && !is_line_end(*p_)) ++p_;
    if (p_ == end_) return true;
    if (*p_ == '\r') {
      ++p_;
      if (p_ == end_) return true;
      if (*p_ != '\n') return false;
    }
    ++p_;
    return true;
  }

  // A number tinyobjloader reads in full and obj_scan.cpp accepts: optional sign, digits with an
  // optional point, an optional exponent of at most kMaxExponentDigits digits, finite as a float.
  bool number(float& out) {
    const char* start = p_;
    if (start != end_ && *start == '+') {
      ++start;
      if (start == end_ || !(is_digit(*start) || *start == '.')) return false;
    }
    double value = 0;
    if (const char* end = short_decimal(start, end_, value)) {
      p_ = end;
    } else {
      const fast_float::from_chars_result r = fast_float::from_chars(start, end_, value);
      if (r.ec != std::errc()) return false;
      // an exponent obj_scan refuses: the reference path gives that error
      if (exponent_too_long(std::string_view(start, std::size_t(r.ptr - start)))) return false;
      p_ = r.ptr;
    }
    out = static_cast<float>(value);
    return at_token_end() && std::isfinite(value) && std::isfinite(out);
  }

  // A face index: optional minus, 1 to 9 digits, not 0.
  bool index(int32_t& out) {
    const bool negative = p_ != end_ && *p_ == '-';
    if (negative) ++p_;
    int32_t value = 0;
    int digits = 0;
    for (; p_ != end_ && is_digit(*p_); ++p_, ++digits) {
      if (digits == 9) return false;  // beyond any file rayvec reads, and int32 overflow
      value = value * 10 + (*p_ - '0');
    }
    if (digits == 0 || value == 0) return false;
    out = negative ? -value : value;
    return true;
  }

 private:
  const char* p_;
  const char* end_;
};

struct Corner {
  std::array<int32_t, 3> index{0, -1, -1};  // v, vt, vn; 0-based (see ObjChunk), -1 = none
  // Which kinds the corner names. A relative index is local to the piece until the join fixes it
  // up, so -1 there is an element of an earlier piece, not "none": only `given` tells.
  std::array<bool, 3> given{true, false, false};
  std::array<bool, 3> relative{false, false, false};
  bool any_relative() const { return relative[0] || relative[1] || relative[2]; }
};

// Whether every token left on the line has an exponent obj_scan accepts (kMaxExponentDigits);
// moves to the line end. obj_scan checks every token of the lines tinyobjloader reads numbers
// from, read here or not: a line it refuses is left to the reference path and its error.
bool exponents_accepted(Cursor& in) {
  for (in.skip_blanks(); !in.at_line_end(); in.skip_blanks())
    if (exponent_too_long(in.token())) return false;
  return true;
}

class ChunkParser {
 public:
  explicit ChunkParser(ObjChunk& chunk) : c_(chunk) {}

  bool vertex_line(Cursor& in, int kind) {
    std::array<float, 3> x{0, 0, 0};
    const int needed = kind == kVt ? 1 : 3;
    for (int k = 0; k < needed; ++k) {
      in.skip_blanks();
      if (in.at_line_end() || !in.number(x[k])) return false;
    }
    if (kind == kVt) {
      in.skip_blanks();  // tinyobjloader reads a second coordinate, 0 when there is none
      if (!in.at_line_end() && !in.number(x[1])) return false;
      c_.texcoords.push_back({x[0], x[1]});
    } else if (kind == kVn) {
      c_.normals.push_back({x[0], x[1], x[2]});
    } else {
      // A position beyond the intersectors' range is an error: the full reader reports it with its line.
      if (!(coordinate_in_range(x[0]) && coordinate_in_range(x[1]) && coordinate_in_range(x[2])))
        return false;
      c_.positions.push_back({x[0], x[1], x[2]});
      if (!vertex_color(in)) return false;
    }
    // the tokens not read (a position's w, what follows a colour or a normal) obj_scan checks too
    return exponents_accepted(in) && in.next_line();
  }

  // The tokens after a position as tinyobjloader reads them: three numbers are a colour (`v x y z r
  // g b`); fewer, or `v x y z w`, none (white). A token that cannot start a number (a comment) ends
  // the numbers; one that starts like a number but is not a plain one is left to the reference path,
  // whose number parser may read it otherwise.
  bool vertex_color(Cursor& in) {
    std::array<float, 3> rgb{1, 1, 1};
    int read = 0;
    for (; read < 3; ++read) {
      in.skip_blanks();
      const char c = in.peek();
      if (in.at_line_end() || !(is_digit(c) || c == '+' || c == '-' || c == '.')) break;
      if (!in.number(rgb[read])) return false;
    }
    if (read == 3) {
      if (c_.colors.empty()) c_.colors.assign(c_.positions.size() - 1, Vec3f{1, 1, 1});
      c_.colors.push_back({rgb[0], rgb[1], rgb[2]});
    } else if (!c_.colors.empty()) {
      c_.colors.push_back({1, 1, 1});
    }
    return true;
  }

  bool face_line(Cursor& in) {
    corners_.clear();
    for (;;) {
      in.skip_blanks();
      if (in.at_line_end()) break;
      // a face too large is an error, which the reference path reports with its line
      if (corners_.size() == std::size_t(kMaxFaceCorners)) return false;
      if (!corner(in, corners_.emplace_back())) return false;
    }
    const std::size_t n = corners_.size();
    if (n < 3) return false;
    const auto first = static_cast<uint32_t>(c_.triangles.size());
    if (n == 4) c_.quads.push_back(first);
    if (n > 4) c_.polygons.push_back({first, static_cast<uint32_t>(n)});
    for (std::size_t i = 1; i + 1 < n; ++i) triangle(corners_[0], corners_[i], corners_[i + 1]);
    return in.next_line();
  }

 private:
  int64_t have(int kind) const {
    return static_cast<int64_t>(kind == kV    ? c_.positions.size()
                                : kind == kVt ? c_.texcoords.size()
                                              : c_.normals.size());
  }

  bool item(Cursor& in, Corner& out, int kind) {
    int32_t raw = 0;
    if (!in.index(raw)) return false;
    const int64_t count = have(kind);
    out.given[kind] = true;
    if (raw > 0) {
      c_.highest_ahead[kind] = std::max(c_.highest_ahead[kind], raw - count);
      out.index[kind] = raw - 1;
    } else {
      const int64_t local = count + raw;
      c_.lowest_relative[kind] = std::min(c_.lowest_relative[kind], local);
      out.index[kind] = static_cast<int32_t>(local);
      out.relative[kind] = true;
    }
    return true;
  }

  // v, v/vt, v//vn, v/vt/vn
  bool corner(Cursor& in, Corner& out) {
    if (!item(in, out, kV)) return false;
    if (in.peek() == '/') {
      in.jump(in.pos() + 1);
      if (in.peek() == '/') {
        in.jump(in.pos() + 1);
        if (!item(in, out, kVn)) return false;
      } else {
        if (!item(in, out, kVt)) return false;
        if (in.peek() == '/') {
          in.jump(in.pos() + 1);
          if (!item(in, out, kVn)) return false;
        }
      }
    }
    return in.at_token_end();
  }

  void triangle(const Corner& a, const Corner& b, const Corner& c) {
    const auto t = static_cast<uint32_t>(c_.triangles.size());
    c_.triangles.push_back({static_cast<uint32_t>(a.index[kV]), static_cast<uint32_t>(b.index[kV]),
                            static_cast<uint32_t>(c.index[kV])});
    corner_indices(c_.triangle_texcoords, t, a, b, c, kVt);
    corner_indices(c_.triangle_normals, t, a, b, c, kVn);
    if (!(a.any_relative() || b.any_relative() || c.any_relative())) return;
    const Corner* corners[3] = {&a, &b, &c};
    for (uint32_t k = 0; k < 3; ++k)
      for (int kind = 0; kind < 3; ++kind)
        if (corners[k]->relative[kind]) c_.relative[kind].push_back(3 * t + k);
  }

  // Appends triangle t's corner indices of one kind. The array stays empty while no triangle has
  // one (ObjChunk): a file of positions only never writes the two arrays of -1 (24 bytes a triangle
  // of fresh memory).
  static void corner_indices(std::vector<std::array<int32_t, 3>>& v, uint32_t t, const Corner& a,
                             const Corner& b, const Corner& c, int kind) {
    if (v.empty()) {
      if (!(a.given[kind] || b.given[kind] || c.given[kind])) return;
      v.assign(t, kNoCornerIndices);
    }
    v.push_back({a.index[kind], b.index[kind], c.index[kind]});
  }

  ObjChunk& c_;
  std::vector<Corner> corners_;  // the face being read; kept for its capacity
};

// The rest of an `s` line as tinyobjloader reads it: nothing (the line is ignored), `off…` (group
// 0) or a group number. Other text tinyobjloader reads with atoi (`s 1.5`, `s -2`, `s x`): left to
// the reference path.
bool smoothing_line(Cursor& in, ObjChunk& chunk) {
  in.skip_blanks();
  const std::string_view value = in.token();
  if (value.empty()) return true;
  uint32_t group = 0;
  if (value.substr(0, 3) != "off") {
    if (value.size() > 9 || !std::all_of(value.begin(), value.end(), is_digit)) return false;
    for (const char c : value) group = group * 10 + static_cast<uint32_t>(c - '0');
  }
  chunk.smoothing.push_back({chunk.triangles.size(), group});
  return true;
}

}  // namespace

void parse_obj_chunk(std::string_view text, ObjChunk& chunk) {
  Cursor in(text.data(), text.data() + text.size());
  ChunkParser parser(chunk);
  bool ok = true;
  while (ok && !in.done()) {
    ++chunk.lines;
    in.skip_blanks();
    // the common lines first, without the keyword comparisons below
    const char c0 = in.peek(), c1 = in.peek(1);
    if (c0 == 'v' && is_blank(c1)) {
      in.jump(in.pos() + 2);
      ok = parser.vertex_line(in, kV);
      continue;
    }
    if (c0 == 'f' && is_blank(c1)) {
      in.jump(in.pos() + 2);
      ok = parser.face_line(in);
      continue;
    }
    const char* line = in.pos();
    const std::string_view key = in.token();
    // Keywords as tinyobjloader tells them apart; the ones obj_scan.cpp checks (v, vn, vt, f)
    // with nothing after them are errors, left to the reference path.
    if (key == "v" || key == "vn" || key == "vt") {
      const int kind = key == "v" ? kV : key == "vt" ? kVt : kVn;
      ok = !in.at_line_end() && parser.vertex_line(in, kind);
    } else if (key == "f") {
      ok = !in.at_line_end() && parser.face_line(in);
    } else if (key == "l" || key == "p") {
      ok = in.next_line();  // lines and points: not drawn, not read (text_for_tinyobjloader)
    } else if (key == "vw") {
      ok = false;  // skin weights: rare, and tinyobjloader may reject them
    } else if (key.substr(0, 6) == "usemtl") {
      // tinyobjloader matches the prefix, even `usemtlname`; the name is the rest of the line
      in.jump(line + 6);
      const char* start = in.pos();
      while (!in.at_line_end()) in.jump(in.pos() + 1);
      chunk.events.push_back(
          {ObjEvent::usemtl, chunk.lines, chunk.triangles.size(),
           written_material_name(std::string_view(start, static_cast<std::size_t>(in.pos() - start)))});
      ok = in.next_line();
    } else if (key == "mtllib" && !in.at_line_end()) {
      in.jump(line + 7);
      const char* start = in.pos();
      while (!in.at_line_end()) in.jump(in.pos() + 1);
      chunk.events.push_back({ObjEvent::mtllib, chunk.lines, chunk.triangles.size(),
                              std::string(start, static_cast<std::size_t>(in.pos() - start))});
      ok = in.next_line();
    } else if (key == "s" && !in.at_line_end()) {
      ok = smoothing_line(in, chunk) && in.next_line();
    } else if (key == "t") {
      ok = exponents_accepted(in) && in.next_line();  // tags: their numbers are not used
    } else {
      ok = in.next_line();  // blank lines, comments, g, o and what tinyobjloader ignores
    }
  }
  chunk.ok = ok;
}

}  // namespace rayvec
