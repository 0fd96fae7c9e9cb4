// Helpers shared by the fuzz harnesses: a private scratch directory per fuzzing process and
// whole-file writes. Loaders that take a path get the fuzz input through a file in it.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace rayvec::fuzz {

// $RAYVEC_FUZZ_SCRATCH (scripts/fuzz.sh makes and removes it), else a new
// "/dev/shm/rayvec-fuzz-XXXXXX" (memory-backed, so file round trips stay cheap) or one under /tmp,
// left behind: libFuzzer ends with _Exit, so no atexit cleanup would run. Made once per process.
inline const std::string& scratch_dir() {
  static const std::string dir = [] {
    if (const char* given = std::getenv("RAYVEC_FUZZ_SCRATCH")) return std::string(given);
    char shm[] = "/dev/shm/rayvec-fuzz-XXXXXX";
    char tmp[] = "/tmp/rayvec-fuzz-XXXXXX";
    const char* made = ::mkdtemp(shm);
    if (!made) made = ::mkdtemp(tmp);
    if (!made) std::abort();
    return std::string(made);
  }();
  return dir;
}

inline std::string write_scratch(const std::string& name, std::string_view bytes) {
  const std::string path = scratch_dir() + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (!bytes.empty()) std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  return path;
}

}  // namespace rayvec::fuzz
