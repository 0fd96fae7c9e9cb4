// load_obj_fast: rayvec's own OBJ geometry reader, the fast path of load_obj (a fifteenth of the
// CPU time of the pre-scan with tinyobjloader; see benchmarks.md#decision-obj-fast-path). It reads the
// strict subset of obj_chunk.h, in pieces on `threads` threads when asked, and builds exactly the ObjModel
// that the reference path (tinyobjloader's reading, polygons cut by triangulate_polygon) gives (same
// triangles and their order, attribute indices, material ids, warnings), except that coordinates are
// correctly rounded where tinyobjloader's own conversion can be one float step off. Anything outside the
// subset — every file with an error among them — goes back to the reference path, which reports it.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "scene/material_names.h"
#include "scene/obj_loader.h"
#include "scene/obj_sample.h"

namespace rayvec {

// The MTL libraries an OBJ's `mtllib` lines name, as the reader sees them.
struct MtlLibraries {
  // Whether a name (a whole `mtllib` line's, see mtllib_text) is an existing file.
  MtlFileExists exists;
  // Loads the library `file` (one name of an `mtllib` line), adding its materials to `by_name`; true
  // if it loaded. Warnings and errors are appended in tinyobjloader's text form, one per line.
  std::function<bool(const std::string& file, std::map<std::string, int>& by_name, std::string& warn,
                     std::string& err)>
      load;
};

// Fills the geometry, attributes and triangle_material of `model` from `text` and returns true, or
// returns false without touching `model` or loading an MTL file when the text needs the reference
// path. `threads`: at most that many pieces and threads, cut by ObjSample::split; 0 means 1
// (load_obj's callers use one: a second is faster only while both cores are idle, and then by
// about a fifth; see benchmarks.md#decision-obj-fast-path).
// tinyobjloader's warnings go to `warn` and the MTL loader's errors to `err`, in file order.
bool load_obj_fast(std::string_view text, int threads, const MtlLibraries& mtl, ObjModel& model,
                   std::string& warn, std::string& err);

// The same with the pieces given: runs of whole lines of `text`, in order, covering it exactly (the
// first may be all of it); one thread each. `sample` is ObjSample(text). load_obj_fast cuts the text
// with ObjSample::split; tests cut it anywhere else, to show that the cuts change nothing.
bool load_obj_pieces(std::string_view text, const ObjSample& sample,
                     const std::vector<std::string_view>& pieces, const MtlLibraries& mtl, ObjModel& model,
                     std::string& warn, std::string& err);

}  // namespace rayvec
