// The CSV inputs of `rayvec visibility`, in the format of the CUDA visibility study (Gallina 2023):
//   verts.csv   one vertex per row, `x,y,z` in scientific notation (-6.195182353258132935e-02);
//               rows of `nan` occur and are kept (their visibility is undefined).
//   meshes.csv  one triangle per row, three 0-based vertex row numbers written as floats
//               (1.000000000000000000e+00).
// Vertex rows are counted over the non-blank lines that do not start with '#'.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/csv_fields.h"
#include "math/vec3.h"

namespace rayvec {

// Reads the vertex rows (non-finite coordinates kept as read). Throws InputError `file:line:` for a
// missing file, a row without exactly 3 fields, or a field that is not a number.
std::vector<Vec3f> read_verts_csv(const std::string& path);
// The parse_* forms read text already in memory, on the OpenMP threads in chunks of about
// `chunk_bytes` (csv_chunks.h); the result does not depend on it.
std::vector<Vec3f> parse_verts_csv(std::string_view text, const std::string& name,
                                   std::size_t chunk_bytes = kCsvChunkBytes);

// Reads the triangles. Throws InputError `file:line:` for a missing file, a row without exactly 3
// fields, a field that is not a number, and an index that is not an integer, is negative, or is not
// below vertex_count.
std::vector<std::array<uint32_t, 3>> read_faces_csv(const std::string& path, std::size_t vertex_count);
std::vector<std::array<uint32_t, 3>> parse_faces_csv(std::string_view text, const std::string& name,
                                                     std::size_t vertex_count,
                                                     std::size_t chunk_bytes = kCsvChunkBytes);

}  // namespace rayvec
