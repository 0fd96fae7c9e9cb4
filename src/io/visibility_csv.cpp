#include "io/visibility_csv.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "geometry/coordinate_range.h"
#include "io/csv_chunks.h"
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

// The parts' rows, in order, as one vector.
template <class T>
std::vector<T> joined(std::vector<std::vector<T>> parts) {
  if (parts.size() == 1) return std::move(parts[0]);
  std::size_t total = 0;
  for (const auto& part : parts) total += part.size();
  std::vector<T> all;
  all.reserve(total);
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace

std::vector<Vec3f> parse_verts_csv(std::string_view text, const std::string& name, std::size_t chunk_bytes) {
  const auto parse = [&](std::vector<Vec3f>& verts, std::string_view line, std::size_t number) {
    if (is_blank_or_comment(line)) return;
    const CsvPlace where{name, number};
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
  };
  return joined(parse_csv_chunks<std::vector<Vec3f>>(text, 1, parse, chunk_bytes));
}

std::vector<std::array<uint32_t, 3>> parse_faces_csv(std::string_view text, const std::string& name,
                                                     std::size_t vertex_count, std::size_t chunk_bytes) {
  using Face = std::array<uint32_t, 3>;
  const auto parse = [&](std::vector<Face>& faces, std::string_view line, std::size_t number) {
    if (is_blank_or_comment(line)) return;
    const CsvPlace where{name, number};
    expect_three(line, where, "three 0-based vertex indices");
    double f[3];
    parse_fields(line, f, 3, where);
    Face face{};
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
  };
  return joined(parse_csv_chunks<std::vector<Face>>(text, 1, parse, chunk_bytes));
}

std::vector<Vec3f> read_verts_csv(const std::string& path) {
  return parse_verts_csv(read_text_file(path), text_name(path));
}

std::vector<std::array<uint32_t, 3>> read_faces_csv(const std::string& path, std::size_t vertex_count) {
  return parse_faces_csv(read_text_file(path), text_name(path), vertex_count);
}

}  // namespace rayvec
