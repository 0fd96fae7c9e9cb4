#include "scene/texture_reads.h"

#include <algorithm>
#include <atomic>
#include <system_error>
#include <thread>

#include "image/image_io.h"
#include "io/input_error.h"
#include "scene/texture_path.h"

namespace rayvec {

TextureRead read_texture_file(const std::string& path) {
  TextureRead read;
  try {
    read.problem = texture_file_problem(path);
    if (read.problem.empty()) read.texture = read_texture(path);
  } catch (const InputError& e) {
    read.problem = std::string("cannot be decoded: ") + e.what();
  } catch (...) {
    read.failure = std::current_exception();
  }
  return read;
}

std::vector<TextureRead> read_texture_files(const std::vector<std::string>& paths, int threads) {
  std::vector<TextureRead> reads(paths.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < paths.size(); i = next++) reads[i] = read_texture_file(paths[i]);
  };
  // this thread reads too: helpers for the rest of `threads`, at most one a file
  const std::size_t wanted = std::min(paths.size(), std::size_t(std::max(threads, 1)));
  std::vector<std::thread> helpers;
  try {
    for (std::size_t t = 1; t < wanted; ++t) helpers.emplace_back(work);
  } catch (const std::system_error&) {
    // no more threads to be had: the ones started and this one share the files
  }
  work();
  for (std::thread& h : helpers) h.join();
  return reads;
}

}  // namespace rayvec
