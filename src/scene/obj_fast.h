// load_obj_fast: rayvec's own OBJ geometry reader, the fast path of load_obj (about 6 times the
// speed of tinyobjloader with the pre-scan; see benchmarks.md#decision-obj-fast-path). It reads the
// strict subset of obj_chunk.h in pieces on up to `threads` threads and builds exactly the ObjModel
// that tinyobjloader's reading gives (same triangles and their order, quad diagonals, attribute
// indices, material ids, warnings), except that coordinates are correctly rounded where
// tinyobjloader's own conversion can be one float step off. Anything outside the subset — every
// file with an error among them — goes back to the reference path, which reports it.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "scene/obj_loader.h"

namespace rayvec {

// Loads the MTL library `file` (as named in `mtllib`), adding its materials to `by_name`; true if
// it loaded. Warnings and errors are appended in tinyobjloader's text form, one per line.
using MtlLibraryLoader = std::function<bool(const std::string& file, std::map<std::string, int>& by_name,
                                            std::string& warn, std::string& err)>;

// Files this large and more are read on two threads when `threads` is 0.
inline constexpr std::size_t kObjParallelBytes = 4u << 20;

// Fills the geometry, attributes and triangle_material of `model` from `text` and returns true, or
// returns false without touching `model` or calling `load_mtl` when the text needs the reference
// path. `threads`: 0 picks (2 for big files, 1 otherwise), else that many pieces and threads.
// tinyobjloader's warnings go to `warn` and the MTL loader's errors to `err`, in file order.
bool load_obj_fast(std::string_view text, int threads, const MtlLibraryLoader& load_mtl, ObjModel& model,
                   std::string& warn, std::string& err);

}  // namespace rayvec
