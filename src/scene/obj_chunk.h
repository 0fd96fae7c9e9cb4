// parse_obj_chunk: rayvec's fast OBJ tokenizer for one piece of a file (a run of whole lines), the
// first stage of load_obj_fast (obj_fast.h). It accepts only a strict subset of OBJ whose meaning is
// certain to match tinyobjloader's — v (with or without a colour)/vn/vt with plain decimal numbers,
// faces of 3 to kMaxFaceCorners corners with `a`, `a/b`, `a//c` or `a/b/c` corners, `l`/`p` lines
// (not read), usemtl/mtllib/g/o/t lines, `s` with a group number or `off`, comments — and reports
// anything else (an error, `vw` lines, lone CR line ends) as "not mine", so that the caller hands the
// whole file to the reference path instead.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "math/vec3.h"
#include "scene/obj_loader.h"

namespace rayvec {

// A line whose effect depends on what came before it in the file (MTL libraries load in file
// order, `usemtl` looks its name up in what has loaded so far); replayed in order after parsing.
struct ObjEvent {
  enum Kind : uint8_t { usemtl, mtllib } kind;
  std::size_t line;      // 1-based, within the chunk
  std::size_t triangle;  // triangles of the chunk before this line
  std::string text;      // usemtl: the name; mtllib: the rest of the line after `mtllib `
};

// Face corner indices are 0-based. Where the file writes a negative (relative) index, the value
// stored is relative to the chunk's first element of that kind (it may be negative: an element of
// an earlier chunk) and its slot is listed in `relative`; the caller adds the chunk's offset.
struct ObjChunk {
  std::vector<Vec3f> positions, normals;
  // per position: its colour (`v x y z r g b`), white where the line gives none; empty while no
  // position of the chunk has one
  std::vector<Vec3f> colors;
  std::vector<std::array<float, 2>> texcoords;
  std::vector<std::array<uint32_t, 3>> triangles;
  // -1: none. Each is empty while no triangle of the chunk gives that kind, then one per triangle.
  std::vector<std::array<int32_t, 3>> triangle_normals, triangle_texcoords;
  // Quads are stored as the triangles (0,1,2), (0,2,3); the first one's index is listed here for
  // the caller to choose the diagonal once every position is known.
  std::vector<uint32_t> quads;
  // Polygons of 5 or more corners are stored as their fan (0,i,i+1), n − 2 triangles from `first`,
  // for the caller to cut them by triangulate_polygon once every position is known.
  struct Polygon {
    uint32_t first, corners;
  };
  std::vector<Polygon> polygons;
  std::array<std::vector<uint32_t>, 3> relative;    // per kind (v, vt, vn): slots 3 * triangle + corner
  std::array<int64_t, 3> lowest_relative{0, 0, 0};  // per kind: the smallest relative value stored
  // per kind: the largest (1-based index - elements of that kind in the chunk before the line); a
  // positive value is an index the chunk does not define itself, valid only if earlier chunks do.
  std::array<int64_t, 3> highest_ahead{INT64_MIN, INT64_MIN, INT64_MIN};
  std::vector<ObjEvent> events;
  // Each `s` line: the chunk's triangles before it and the smoothing group it starts (0 = off).
  struct Smoothing {
    std::size_t triangle;
    uint32_t group;
  };
  std::vector<Smoothing> smoothing;
  std::size_t lines = 0;
  bool ok = true;  // false: the text needs the reference path
};

// Parses `text` (whole lines: it starts at a line start and ends after a line end or at the end of
// the file). On return `chunk.ok` says whether the text lies in the fast subset.
void parse_obj_chunk(std::string_view text, ObjChunk& chunk);

}  // namespace rayvec
