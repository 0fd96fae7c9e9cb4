#include "io/visibility_csv.h"

#include <cmath>
#include <cstdio>

#include "geometry/coordinate_range.h"
#include "io/csv_fields.h"
#include "io/text_file.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

void expect_three(std::string_view line, const CsvPlace& where, const char* what) {
  const std::size_t n = count_fields(line);
  if (n != 3) check_no_inner_cr(line, where);
  if (n != 3)
    throw InputError(
        where.file, where.line,
        "found " + std::to_string(n) + (n == 1 ? " field" : " fields") + ", expected 3 (" + what + ")");
}

std::string show(double x, const char* format = "%.17g") {
  char buf[40];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

}  // namespace

std::vector<Vec3f> parse_verts_csv(std::string_view text, const std::string& name) {
  std::vector<Vec3f> verts;
  verts.reserve(text.size() / 72 + 1);  // rows of three %.18e numbers are ~75 bytes
  LineCursor cursor(text);
  std::string_view line;
  while (cursor.next(line)) {
    if (is_blank_or_comment(line)) continue;
    const CsvPlace where{name, cursor.line_number()};
    expect_three(line, where, "x,y,z");
    float f[3];
    parse_fields(line, f, 3, where);
    // Non-finite coordinates are allowed (their faces are dropped, their answer is nan); huge finite
    // ones would give silently wrong answers.
    for (int k = 0; k < 3; ++k)
      if (std::isfinite(f[k]) && !coordinate_in_range(f[k]))
        throw InputError(name, where.line,
                         "coordinate " + std::to_string(k + 1) + " (" + show(double(f[k]), "%.9g") +
                             ") is beyond " + kCoordinateRangeText);
    verts.push_back({f[0], f[1], f[2]});
  }
  return verts;
}

std::vector<std::array<uint32_t, 3>> parse_faces_csv(std::string_view text, const std::string& name,
                                                     std::size_t vertex_count) {
  std::vector<std::array<uint32_t, 3>> faces;
  faces.reserve(text.size() / 72 + 1);
  LineCursor cursor(text);
  std::string_view line;
  while (cursor.next(line)) {
    if (is_blank_or_comment(line)) continue;
    const CsvPlace where{name, cursor.line_number()};
    expect_three(line, where, "three 0-based vertex indices");
    double f[3];
    parse_fields(line, f, 3, where);
    std::array<uint32_t, 3> face{};
    for (int k = 0; k < 3; ++k) {
      // the message only when there is one: formatting it for every field was a third of a
      // million-face run
      const auto field = [&] { return "field " + std::to_string(k + 1) + " (" + show(f[k]) + ")"; };
      if (!(f[k] == std::floor(f[k])))  // NaN and inf fail here too
        throw InputError(name, where.line, field() + " is not an integer vertex index");
      if (f[k] < 0) throw InputError(name, where.line, field() + " is a negative vertex index");
      if (!(f[k] < static_cast<double>(vertex_count)))
        throw InputError(
            name, where.line,
            field() + " is out of range: the vertex file has " + std::to_string(vertex_count) + " rows" +
                (vertex_count ? " (indices 0 to " + std::to_string(vertex_count - 1) + ")" : std::string()));
      face[k] = static_cast<uint32_t>(f[k]);
    }
    faces.push_back(face);
  }
  return faces;
}

std::vector<Vec3f> read_verts_csv(const std::string& path) {
  return parse_verts_csv(read_text_file(path), text_name(path));
}

std::vector<std::array<uint32_t, 3>> read_faces_csv(const std::string& path, std::size_t vertex_count) {
  return parse_faces_csv(read_text_file(path), text_name(path), vertex_count);
}

}  // namespace rayvec
