#include "io/rays_csv.h"

#include <cmath>
#include <cstdio>

#include "geometry/coordinate_range.h"
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

RayBatch parse_rays_csv(std::string_view text, const std::string& name) {
  RayBatch rays;
  // A typical line is ~60-100 bytes: reserving avoids regrowing eight arrays for millions of rays.
  rays.reserve(text.size() / 64 + 1);
  LineCursor cursor(text);
  std::string_view line;
  bool data_seen = false;
  while (cursor.next(line)) {
    if (is_blank_or_comment(line)) continue;
    const CsvPlace where{name, cursor.line_number()};
    const std::size_t n = count_fields(line);
    if (!data_seen && is_header(line)) {
      data_seen = true;
      continue;
    }
    data_seen = true;
    if (n != 6 && n != 8) {
      check_no_inner_cr(line, where);
      throw InputError(name, where.line,
                       "found " + std::to_string(n) + (n == 1 ? " field" : " fields") +
                           ", expected 6 (ox,oy,oz,dx,dy,dz) or 8 (ox,oy,oz,dx,dy,dz,tmin,tmax)");
    }
    float f[8] = {0, 0, 0, 0, 0, 0, 0.0f, kInf};
    parse_fields(line, f, n, where);
    validate(f, n, where);
    rays.push_back(Ray{{f[0], f[1], f[2]}, {f[3], f[4], f[5]}, f[6], f[7]});
  }
  return rays;
}

RayBatch read_rays_csv(const std::string& path) {
  return parse_rays_csv(read_text_file(path), text_name(path));
}

}  // namespace rayvec
