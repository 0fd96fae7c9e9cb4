// RAYS.csv: the rays `rayvec hits` traces, one per line (format in docs/formats.md).
//   ox,oy,oz,dx,dy,dz              tmin = 0, tmax = +inf
//   ox,oy,oz,dx,dy,dz,tmin,tmax
// Lines whose first non-blank character is '#' and blank lines are skipped; one optional header
// line naming the columns (`ox,oy,oz,dx,dy,dz[,tmin,tmax]`) is accepted; LF or CRLF line ends.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "io/csv_fields.h"
#include "rays/ray.h"

namespace rayvec {

// Reads `path`. Throws InputError `file:line: what is wrong` for a missing file, a line with
// another number of fields than 6 or 8, a field that is not a number, a NaN or infinite origin or
// direction coordinate, a zero direction, a NaN tmin or tmax, or tmin > tmax (tmax = inf is fine).
RayBatch read_rays_csv(const std::string& path);

// The same on text already in memory; `name` is the file name used in messages. The lines are parsed
// on the OpenMP threads in chunks of about `chunk_bytes` (csv_chunks.h); the result does not depend on it.
RayBatch parse_rays_csv(std::string_view text, const std::string& name,
                        std::size_t chunk_bytes = kCsvChunkBytes);

}  // namespace rayvec
