#include "io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>

#include "io/input_error.h"

namespace rayvec {
namespace {

// A small fixed registry so a signal handler can unlink temporaries without allocating.
constexpr int kSlots = 16;
std::array<std::atomic<const char*>, kSlots> g_open_temps{};

void register_temp(const char* path) {
  for (auto& slot : g_open_temps) {
    const char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, path)) return;
  }
}

void unregister_temp(const char* path) {
  for (auto& slot : g_open_temps) {
    const char* expected = path;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

}  // namespace

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temp_(path_ + ".tmp-" + std::to_string(::getpid())) {
  // The temporary sits next to the path, so a directory given as output would only fail at the
  // rename, after all the work: refuse it now.
  struct stat st {};
  if (::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw RuntimeError("cannot write " + path_ + ": it is a directory (give a file name)");
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_)
    throw RuntimeError("cannot write " + path_ + ": " + std::strerror(errno) +
                       " (check that the directory exists and is writable)");
  register_temp(temp_.c_str());
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (file_) std::fclose(file_);
  unregister_temp(temp_.c_str());
  std::remove(temp_.c_str());
}

void AtomicFile::commit() {
  const bool write_ok = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool close_ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!write_ok || !close_ok) throw RuntimeError("cannot write " + path_ + ": " + std::strerror(errno));
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw RuntimeError("cannot rename " + temp_ + " to " + path_ + ": " + std::strerror(errno));
  unregister_temp(temp_.c_str());
  committed_ = true;
}

void remove_open_temporaries_on_signal() {
  for (auto& slot : g_open_temps) {
    const char* p = slot.load();
    if (p) ::unlink(p);
  }
}

}  // namespace rayvec
