// The CSV readers parse in chunks on several threads (csv_chunks.h) and give what one serial pass
// gives: the same rows in the same order whatever the chunk size (a byte, a few lines, everything),
// the same line numbers, and of several bad lines the first one's error.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/csv_chunks.h"
#include "io/input_error.h"
#include "io/rays_csv.h"
#include "io/visibility_csv.h"

namespace rayvec {
namespace {

constexpr std::size_t kChunkSizes[] = {1, 7, 64, 1000, kCsvChunkBytes};

// Two threads at least, so that chunks really are parsed concurrently.
struct TwoThreads {
  int before = omp_get_max_threads();
  TwoThreads() { omp_set_num_threads(2); }
  ~TwoThreads() { omp_set_num_threads(before); }
};

// A rays file with what the reader skips or accepts around its rows: a comment and a header first,
// blank lines, CRLF ends, 6- and 8-field rows, and no final newline.
std::string rays_text(int rows) {
  std::string text = "# made by a test\r\nox,oy,oz,dx,dy,dz\r\n";
  for (int i = 0; i < rows; ++i) {
    text += std::to_string(i) + ".5,-" + std::to_string(i % 7) + ",3,0,0," + std::to_string(1 + i % 3);
    if (i % 5 == 0) text += ",0.25," + std::to_string(10 + i);
    text += i % 11 == 0 ? "\r\n" : "\n";
    if (i % 13 == 0) text += "\n   \n# note\n";
  }
  text += "1,2,3,4,5,6";
  return text;
}

std::string error_of(const std::string& text, std::size_t chunk) {
  try {
    parse_rays_csv(text, "r.csv", chunk);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CsvChunks, RaysAreTheSameWhateverTheChunkSize) {
  const TwoThreads threads;
  const std::string text = rays_text(500);
  const RayBatch serial = parse_rays_csv(text, "r.csv", text.size() + 1);
  ASSERT_EQ(serial.size(), 501u);
  for (std::size_t chunk : kChunkSizes) {
    const RayBatch rays = parse_rays_csv(text, "r.csv", chunk);
    ASSERT_EQ(rays.size(), serial.size()) << "chunks of " << chunk;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      EXPECT_EQ(rays.ox[i], serial.ox[i]) << "chunks of " << chunk << ", ray " << i;
      EXPECT_EQ(rays.dz[i], serial.dz[i]) << "chunks of " << chunk << ", ray " << i;
      EXPECT_EQ(rays.tmin[i], serial.tmin[i]) << "chunks of " << chunk << ", ray " << i;
      EXPECT_EQ(rays.tmax[i], serial.tmax[i]) << "chunks of " << chunk << ", ray " << i;
    }
  }
}

TEST(CsvChunks, AHeaderAloneOrNothingGivesNoRays) {
  for (std::size_t chunk : kChunkSizes) {
    EXPECT_EQ(parse_rays_csv("ox,oy,oz,dx,dy,dz", "r.csv", chunk).size(), 0u);
    EXPECT_EQ(parse_rays_csv("ox,oy,oz,dx,dy,dz\n", "r.csv", chunk).size(), 0u);
    EXPECT_EQ(parse_rays_csv("", "r.csv", chunk).size(), 0u);
    EXPECT_EQ(parse_rays_csv("\n# only a comment\n", "r.csv", chunk).size(), 0u);
  }
}

TEST(CsvChunks, TheFirstBadLineIsReportedWithItsLineNumber) {
  const TwoThreads threads;
  std::vector<std::string> lines;
  for (int i = 0; i < 400; ++i) lines.push_back("0,0,0,0,0,1");
  lines[250] = "0,0,0,0,0,0";     // line 251: a zero direction
  lines[330] = "0,0,zero,0,0,1";  // line 331: not a number
  lines[390] = "0,0,0,0,0,1,2";   // line 391: seven fields
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  for (std::size_t chunk : kChunkSizes) {
    const std::string e = error_of(text, chunk);
    EXPECT_EQ(e.rfind("r.csv:251: direction is zero", 0), 0u) << "chunks of " << chunk << ": " << e;
  }
  lines[250] = lines[0];
  text.clear();
  for (const std::string& l : lines) text += l + "\n";
  for (std::size_t chunk : kChunkSizes)
    EXPECT_EQ(error_of(text, chunk).rfind("r.csv:331: field 3 'zero' is not a number", 0), 0u) << chunk;
}

TEST(CsvChunks, VisibilityRowsAndErrorsAreTheSameWhateverTheChunkSize) {
  const TwoThreads threads;
  std::string verts = "# vertices\n", faces;
  for (int i = 0; i < 300; ++i) {
    verts += std::to_string(i) + ".0,-1.5e-2," + (i % 17 == 0 ? "nan" : std::to_string(i % 9)) + "\n";
    if (i % 10 == 0) verts += "\n";
    faces += std::to_string(i) + "," + std::to_string((i * 7) % 300) + ".0," +
             std::to_string((i * 13) % 300) + "\r\n";
  }
  const auto serial_verts = parse_verts_csv(verts, "verts.csv", verts.size() + 1);
  const auto serial_faces = parse_faces_csv(faces, "meshes.csv", serial_verts.size(), faces.size() + 1);
  ASSERT_EQ(serial_verts.size(), 300u);
  ASSERT_EQ(serial_faces.size(), 300u);
  for (std::size_t chunk : kChunkSizes) {
    const auto v = parse_verts_csv(verts, "verts.csv", chunk);
    const auto f = parse_faces_csv(faces, "meshes.csv", v.size(), chunk);
    ASSERT_EQ(v.size(), serial_verts.size()) << chunk;
    ASSERT_EQ(f, serial_faces) << chunk;
    for (std::size_t i = 0; i < v.size(); ++i)
      EXPECT_EQ(std::to_string(v[i].z), std::to_string(serial_verts[i].z)) << chunk << ", vertex " << i;
  }
  const std::string bad = faces + "1,2,300\n" + faces + "1,2,-1\n";  // lines 301 and 602
  for (std::size_t chunk : kChunkSizes) {
    try {
      parse_faces_csv(bad, "meshes.csv", 300, chunk);
      ADD_FAILURE() << "no error with chunks of " << chunk;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("meshes.csv:301: field 3 (300) is out of range", 0), 0u)
          << chunk << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace rayvec
