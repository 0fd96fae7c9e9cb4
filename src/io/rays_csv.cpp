#include "io/rays_csv.h"

#include <cmath>
#include <cstdio>

#include "geometry/coordinate_range.h"
#include "io/csv_chunks.h"
#include "io/csv_fields.h"
#include "io/text_file.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

bool is_header(std::string_view line) {
  std::string compact;
  for (char c : line)
    if (c != ' ' && c != '\t' && c != '\r') compact += c;
  return compact == "ox,oy,oz,dx,dy,dz" || compact == "ox,oy,oz,dx,dy,dz,tmin,tmax";
}

std::string show(float x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

// The checks a ray needs beyond parsing; values as read, in CSV order.
void validate(const float* f, std::size_t n, const CsvPlace& where) {
  for (int i = 0; i < 6; ++i) {
    if (std::isfinite(f[i])) continue;
    const char* part = i < 3 ? "origin" : "direction";
    static const char* const kNames[] = {"ox", "oy", "oz", "dx", "dy", "dz"};
    throw InputError(where.file, where.line,
                     std::string(part) + " must be finite, but " + kNames[i] + " is " + show(f[i]));
  }
  if (f[3] == 0.0f && f[4] == 0.0f && f[5] == 0.0f)
    throw InputError(where.file, where.line, "direction is zero (dx = dy = dz = 0)");
  for (int i = 0; i < 3; ++i) {
    static const char* const kNames[] = {"ox", "oy", "oz"};
    if (!coordinate_in_range(f[i]))
      throw InputError(where.file, where.line,
                       std::string("origin coordinate ") + kNames[i] + " = " + show(f[i]) + " is beyond " +
                           kCoordinateRangeText);
  }
  const float longest = largest_component({f[3], f[4], f[5]});
  if (longest < kMinDirection || longest > kMaxDirection)
    throw InputError(where.file, where.line,
                     "direction (" + show(f[3]) + ", " + show(f[4]) + ", " + show(f[5]) + ") is too " +
                         (longest < kMinDirection ? "short" : "long") +
                         ": its largest component must be between 1e-6 and 1e16 in magnitude, where the "
                         "float intersectors answer correctly (scale it: t is measured in units of the "
                         "direction; see docs/formats.md, Coordinate range)");
  if (n == 8) {
    if (std::isnan(f[6]) || std::isnan(f[7]))
      throw InputError(where.file, where.line,
                       std::string(std::isnan(f[6]) ? "tmin" : "tmax") +
                           " is NaN (tmin and tmax must be numbers; "
                           "tmax may be inf)");
    if (f[6] > f[7])
      throw InputError(where.file, where.line,
                       "tmin (" + show(f[6]) + ") is greater than tmax (" + show(f[7]) + ")");
  }
}

}  // namespace

RayBatch parse_rays_csv(std::string_view text, const std::string& name, std::size_t chunk_bytes) {
  // The first line with data may name the columns: found here, then the rays after it in chunks.
  LineCursor cursor(text);
  std::string_view line;
  std::size_t start = text.size(), first_line = 1;  // where the rays begin, and that line's number
  for (std::size_t at = cursor.position(); cursor.next(line); at = cursor.position()) {
    if (is_blank_or_comment(line)) continue;
    const bool header = is_header(line);
    start = header ? std::min(cursor.position(), text.size()) : at;
    first_line = cursor.line_number() + (header ? 1 : 0);
    break;
  }
  const auto parse = [&](RayBatch& rays, std::string_view row, std::size_t number) {
    if (is_blank_or_comment(row)) return;
    const CsvPlace where{name, number};
    const std::size_t n = count_fields(row);
    if (n != 6 && n != 8) {
      check_no_inner_cr(row, where);
      throw InputError(name, where.line,
                       "found " + std::to_string(n) + (n == 1 ? " field" : " fields") +
                           ", expected 6 (ox,oy,oz,dx,dy,dz) or 8 (ox,oy,oz,dx,dy,dz,tmin,tmax)");
    }
    float f[8] = {0, 0, 0, 0, 0, 0, 0.0f, kInf};
    parse_fields(row, f, n, where);
    validate(f, n, where);
    rays.push_back(Ray{{f[0], f[1], f[2]}, {f[3], f[4], f[5]}, f[6], f[7]});
  };
  const std::vector<RayBatch> parts =
      parse_csv_chunks<RayBatch>(text.substr(start), first_line, parse, chunk_bytes);
  RayBatch rays;
  std::size_t total = 0;
  for (const RayBatch& part : parts) total += part.size();
  rays.reserve(total);
  for (const RayBatch& part : parts) rays.append(part);
  return rays;
}

RayBatch read_rays_csv(const std::string& path) {
  return parse_rays_csv(read_text_file(path), text_name(path));
}

}  // namespace rayvec
