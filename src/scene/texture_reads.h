// Reading a model's map_Kd files, several at once: a model with dozens of textures spends most of
// its load decoding them, and each file is independent of the others.
#pragma once
#include <exception>
#include <string>
#include <vector>

#include "image/texture.h"

namespace rayvec {

// The outcome of reading one texture file: the texture, or why it cannot be used (`problem`, for
// the warning: texture_file_problem's reason or "cannot be decoded: …"), or a failure that is not
// the file's fault (a missing image module: RuntimeError; out of memory) to rethrow on the
// caller's thread.
struct TextureRead {
  Texture texture;
  std::string problem;
  std::exception_ptr failure;
};

// Reads one texture file (texture_path.h's checks, then read_texture); never throws.
TextureRead read_texture_file(const std::string& path);

// read_texture_file of each path, on up to `threads` threads (a thread a file at most); the
// results in the order of `paths`, the same whatever the thread count.
std::vector<TextureRead> read_texture_files(const std::vector<std::string>& paths, int threads);

}  // namespace rayvec
