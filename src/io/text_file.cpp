#include "io/text_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "io/csv_fields.h"
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

[[noreturn]] void binary(const std::string& path, std::string_view text, std::size_t nul) {
  const auto line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + nul, '\n'));
  throw InputError(path, line,
                   "contains a NUL byte: this is binary data, not a text file (UTF-16 or UTF-32 "
                   "text must be saved as UTF-8)");
}

constexpr std::size_t kMapFrom = std::size_t(1) << 20;  // smaller files are copied: cheap either way

[[noreturn]] void utf16(const std::string& path) {
  throw InputError(path, 0,
                   "is UTF-16 text (it starts with a UTF-16 byte-order mark); save it as UTF-8 or ASCII");
}

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

// The one file mapped at a time (inputs are read one after another) and its name, for the SIGBUS
// handler: a fault inside it means the file shrank under the mapping.
std::atomic<const char*> mapped_begin{nullptr};
std::atomic<std::size_t> mapped_size{0};
char mapped_name[512];

void on_sigbus(int sig, siginfo_t* info, void*) {
  const char* begin = mapped_begin.load();
  const auto* at = static_cast<const char*>(info->si_addr);
  if (begin && at >= begin && at < begin + mapped_size.load()) {
    static const char prefix[] = "rayvec: ";
    static const char suffix[] = " was truncated while it was being read\n";
    ssize_t ignored = write(2, prefix, sizeof prefix - 1);
    ignored = write(2, mapped_name, std::strlen(mapped_name));
    ignored = write(2, suffix, sizeof suffix - 1);
    (void)ignored;
    _exit(1);
  }
  signal(sig, SIG_DFL);  // not ours: the default action (a core dump), as without the handler
  raise(sig);
}

void watch_mapping(const char* begin, std::size_t size, const std::string& path) {
  static const bool installed = [] {
    struct sigaction sa {};
    sa.sa_sigaction = on_sigbus;
    sa.sa_flags = SA_SIGINFO;
    sigemptyset(&sa.sa_mask);
    return sigaction(SIGBUS, &sa, nullptr) == 0;
  }();
  (void)installed;
  std::snprintf(mapped_name, sizeof mapped_name, "%s", path.c_str());
  mapped_size.store(size);
  mapped_begin.store(begin);
}

}  // namespace

TextFile::TextFile(const std::string& path) {
  struct stat st {};
  const int fd = path == "-" ? -1 : open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && std::size_t(st.st_size) >= kMapFrom) {
    const std::size_t size = static_cast<std::size_t>(st.st_size);
    if (size > max_input_bytes()) {
      close(fd);
      too_large(path);
    }
    void* p = mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    close(fd);
    if (p != MAP_FAILED) {
      map_ = p;
      map_size_ = size;
      text_ = std::string_view(static_cast<const char*>(p), size);
      watch_mapping(static_cast<const char*>(p), size, path);
      try {
        if (starts_with(text_, "\xFF\xFE") || starts_with(text_, "\xFE\xFF")) utf16(path);
        if (const std::size_t nul = text_.find('\0'); nul != std::string_view::npos) binary(path, text_, nul);
      } catch (...) {  // no destructor runs for a constructor that throws
        unmap();
        throw;
      }
      if (starts_with(text_, "\xEF\xBB\xBF")) text_.remove_prefix(3);  // UTF-8 byte-order mark
      return;
    }
  } else if (fd >= 0) {
    close(fd);
  }
  owned_ = read_text_file(path);  // streams, small files, and where mapping fails
  text_ = owned_;
}

TextFile::TextFile(TextFile&& other) noexcept
    : owned_(std::move(other.owned_)), map_(other.map_), map_size_(other.map_size_), text_(other.text_) {
  if (!map_) text_ = owned_;
  other.map_ = nullptr;
  other.map_size_ = 0;
  other.text_ = {};
}

TextFile::~TextFile() { unmap(); }

void TextFile::unmap() {
  if (!map_) return;
  if (mapped_begin.load() == static_cast<const char*>(map_)) mapped_begin.store(nullptr);
  munmap(map_, map_size_);
  map_ = nullptr;
  text_ = {};
}

namespace {

// RAYVEC_MAX_INPUT_MB's megabytes: 0 when unset or empty, nullopt when not 1 to 2^40 − 1 in decimal digits.
std::optional<std::size_t> limit_from_environment() {
  const char* env = std::getenv("RAYVEC_MAX_INPUT_MB");
  if (!env || !*env) return 0;
  std::size_t mb = 0, digits = 0;
  for (const char* c = env; *c; ++c, ++digits) {
    if (*c < '0' || *c > '9' || digits == 13) return std::nullopt;  // 2^40 has 13 digits
    mb = mb * 10 + std::size_t(*c - '0');
  }
  if (mb == 0 || mb >= (std::size_t(1) << 40)) return std::nullopt;
  return mb;
}

}  // namespace

std::size_t max_input_bytes() {
  const std::optional<std::size_t> mb = limit_from_environment();
  return (mb && *mb ? *mb : kDefaultLimitMb) * 1000000;
}

bool input_limit_from_environment() { return limit_from_environment().value_or(0) > 0; }

std::optional<std::string> input_limit_problem() {
  if (limit_from_environment()) return std::nullopt;
  return "RAYVEC_MAX_INPUT_MB: '" + printable(std::getenv("RAYVEC_MAX_INPUT_MB")) +
         "' is not a number of megabytes (a whole number from 1 to 1099511627775, e.g. "
         "RAYVEC_MAX_INPUT_MB=16000; unset it for the default " +
         std::to_string(kDefaultLimitMb) + ")";
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
    if (before == 0 && (text.rfind("\xFF\xFE", 0) == 0 || text.rfind("\xFE\xFF", 0) == 0)) utf16(path);
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
