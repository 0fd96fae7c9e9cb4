// load_obj: a Wavefront OBJ (and its MTL files) through tinyobjloader, validated.
// obj_loader.cpp is the only file that includes tiny_obj_loader.h.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/material.h"
#include "geometry/triangle_mesh.h"

namespace rayvec {

// A triangle's corner indices where its face gives none of that kind (normal or texture coordinate).
inline constexpr std::array<int32_t, 3> kNoCornerIndices{-1, -1, -1};

struct ObjModel {
  std::string source;  // the file it was read from (for messages)
  // Triangles in file order after triangulating polygons as tinyobjloader does; triangle id = index.
  TriangleMesh mesh;
  std::vector<int32_t> triangle_material;  // per triangle: index into materials, -1 = none
  std::vector<Material> materials;  // from the MTL files (mtl_file.h): validated, map_Kd absolute or ""
  // Optional per-corner attributes: -1 where the face gives none. triangle_normals (and
  // triangle_texcoords) is empty when no face gives any normal (texture coordinate), else it holds
  // one entry per triangle.
  std::vector<Vec3f> normals;
  std::vector<std::array<int32_t, 3>> triangle_normals;
  // per position: its colour (`v x y z r g b`, as written), white where the line gives none; empty
  // when no position has one
  std::vector<Vec3f> colors;
  std::vector<std::array<float, 2>> texcoords;
  std::vector<std::array<int32_t, 3>> triangle_texcoords;
  // per triangle: the smoothing group of its face (`s N`; 0 = `s off` or none), empty when no face is
  // in one. The scene shades a triangle of a group whose face gives no normals with normals averaged
  // over the group (smooth_normals.h).
  std::vector<uint32_t> triangle_smoothing;
  std::vector<std::string> warnings;  // non-fatal problems (e.g. a missing MTL file), one per line
};

// How load_obj reads: rayvec's fast reader where the file allows (obj_fast.h), else tinyobjloader.
// Build it with designated initializers ({.reference = true}): its fields convert into each other, so
// a positional {0, true} silently changes meaning when a field is added.
struct ObjLoadOptions {
  int threads = 0;  // the fast reader's threads (pieces of the file); 0: by available_threads
  // The threads the caller may use (its --threads): with two or more, a file of kObjTwoThreadsFrom
  // bytes and more is parsed in two pieces on two threads, a smaller one on one.
  int available_threads = 1;
  bool reference = false;  // tinyobjloader only: the reference the fast reader is tested against
};

// From this size two threads parse an OBJ faster than one (benchmarks.md#decision-obj-fast-path).
inline constexpr std::size_t kObjTwoThreadsFrom = std::size_t(16) << 20;

// Seconds per phase of one load_obj, for `rayvec bench obj`.
struct ObjLoadTimes {
  double read = 0;     // the file into memory
  double check = 0;    // obj_scan's check (the reference path only)
  double parse = 0;    // the fast reader, or tinyobjloader
  double convert = 0;  // tinyobjloader's output into an ObjModel, and the materials
  bool fast = false;   // whether the fast reader took the file
  int threads = 1;     // the threads (pieces) the fast reader was given
};

// Loads and validates `path`. Throws InputError (`file:line: what is wrong`) for a missing or
// unreadable file, a face index out of range, a vertex coordinate that is not a finite number (the
// loader reads `nan`/`inf` text itself, because tinyobjloader silently turns them into 0), and
// files with no triangles.
ObjModel load_obj(const std::string& path, const ObjLoadOptions& options = {}, ObjLoadTimes* times = nullptr);

}  // namespace rayvec
