#include "io/text_file.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "io/input_error.h"
#include "platform/large_buffer.h"

namespace rayvec {
namespace {

constexpr std::size_t kDefaultLimitMb = 4096;

[[noreturn]] void too_large(const std::string& path) {
  throw InputError(path, 0,
                   "is larger than the " + std::to_string(max_input_bytes() / 1000000) +
                       " MB input limit; set RAYVEC_MAX_INPUT_MB to raise it (e.g. "
                       "RAYVEC_MAX_INPUT_MB=16000) if this really is the file you meant");
}

[[noreturn]] void binary(const std::string& path, const std::string& text, std::size_t nul) {
  const auto line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + nul, '\n'));
  throw InputError(path, line,
                   "contains a NUL byte: this is binary data, not a text file (UTF-16 or UTF-32 "
                   "text must be saved as UTF-8)");
}

}  // namespace

std::size_t max_input_bytes() {
  const char* env = std::getenv("RAYVEC_MAX_INPUT_MB");
  std::size_t mb = kDefaultLimitMb;
  if (env && *env) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(env, &end, 10);
    if (*end == '\0' && v > 0 && v < (1ull << 40)) mb = static_cast<std::size_t>(v);
  }
  return mb * 1000000;
}

std::string read_text_file(const std::string& given) {
  // "-" is standard input (named "stdin" in messages), as `-o -` is standard output.
  const bool from_stdin = given == "-";
  const std::string path = from_stdin ? "stdin" : given;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(
      std::fopen(from_stdin ? "/dev/stdin" : path.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  const std::size_t limit = max_input_bytes();
  struct stat st {};
  if (fstat(fileno(f.get()), &st) == 0 && S_ISREG(st.st_mode) &&
      static_cast<unsigned long long>(st.st_size) > limit)
    too_large(path);
  std::string text;
  // One allocation for a regular file: growing by doubling would copy a big file several times.
  if (S_ISREG(st.st_mode) && st.st_size > 0) {
    text.reserve(static_cast<std::size_t>(st.st_size));
    advise_huge_pages(text.data(), text.capacity());
  }
  char buffer[1 << 16];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) {
    if (text.size() + got > limit) too_large(path);
    const std::size_t before = text.size();
    text.append(buffer, got);
    if (before == 0 && (text.rfind("\xFF\xFE", 0) == 0 || text.rfind("\xFE\xFF", 0) == 0))
      throw InputError(path, 0,
                       "is UTF-16 text (it starts with a UTF-16 byte-order mark); save it as "
                       "UTF-8 or ASCII");
    // Checked per block so that /dev/zero or a binary stream fails at its first block.
    if (const std::size_t nul = text.find('\0', before); nul != std::string::npos) binary(path, text, nul);
  }
  if (std::ferror(f.get())) {  // e.g. EISDIR: fopen accepts a directory
    const int err = errno;
    throw InputError(path, 0, std::string("cannot read: ") + std::strerror(err));
  }
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte-order mark
  return text;
}

}  // namespace rayvec
