// File names as OBJ and MTL files in the wild write them (an MTL library in `mtllib`, a texture in
// `map_Kd`), and the checks a texture passes before it is decoded. Shared by both OBJ readers.
#pragma once
#include <string>

namespace rayvec {

// The file `name` (as written after map_Kd or mtllib, options and quotes already removed) refers to,
// for a file in directory `dir` that names it: a relative name is relative to that file; Windows
// separators (`.\tex\a.jpg`) are read as `/` unless a file with the literal name exists; when the
// named file does not exist but a file with its last component does in dir (an exporter's absolute path
// from another machine, `C:\models\a.jpg`), that file; failing all of these, the same two names
// with each missing component matched regardless of ASCII case (`Wood.JPG` for wood.jpg, as a
// case-insensitive file system would). Returns an absolute, normalized path (the best guess when
// nothing exists, for the message).
std::string resolve_named_file(const std::string& name, const std::string& dir);

// Why the texture at `path` cannot be used, or "" when it can: it does not exist, cannot be looked
// up, is not a regular file (a device such as /dev/zero or a FIFO would be read forever), cannot be
// opened for reading, or is larger than the input limit (max_input_bytes, RAYVEC_MAX_INPUT_MB).
std::string texture_file_problem(const std::string& path);

}  // namespace rayvec
