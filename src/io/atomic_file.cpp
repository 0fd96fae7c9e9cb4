#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
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

RuntimeError cannot_write(const std::string& path, int err) {
  return RuntimeError("cannot write " + path + ": " + std::strerror(err) +
                      " (check that the directory exists and is writable)");
}

struct Target {
  std::string path;  // what is replaced or written through
  bool write_through = false;
};

std::string link_text(const std::string& path) {
  std::string text(4096, '\0');
  const ssize_t n = ::readlink(path.c_str(), text.data(), text.size());
  text.resize(n > 0 ? std::size_t(n) : 0);
  return text;
}

// Decides how `path` is written (the table in atomic_file.h). A symbolic link is followed with
// stat(), not realpath(), so the kernel's own links (/dev/stdout -> /proc/self/fd/1 -> pipe:[..])
// still resolve to what they stand for.
Target resolve_target(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return {path, false};  // nothing there yet: open reports errors
  std::string target = path;
  if (S_ISLNK(st.st_mode)) {
    if (::stat(path.c_str(), &st) != 0) {
      const int err = errno;
      if (err == ENOENT)
        throw InputError(path, 0,
                         "is a symbolic link to " + link_text(path) +
                             ", which does not exist (create the target, or remove the link)");
      throw cannot_write(path, err);
    }
    if (S_ISREG(st.st_mode)) {
      // The temporary must sit beside the file the link names, so the rename lands there.
      char* real = ::realpath(path.c_str(), nullptr);
      if (!real) throw cannot_write(path, errno);
      target = real;
      std::free(real);
    }
  }
  if (S_ISREG(st.st_mode)) return {target, false};
  if (S_ISDIR(st.st_mode))
    throw RuntimeError("cannot write " + path + ": it is a directory (give a file name)");
  if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) return {target, true};
  const char* what = S_ISSOCK(st.st_mode)  ? "a socket"
                     : S_ISBLK(st.st_mode) ? "a block device"
                                           : "a special file";
  throw InputError(path, 0,
                   std::string("is ") + what +
                       ": rayvec writes only regular files, FIFOs and character devices such as /dev/null "
                       "(give a file name)");
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  const Target t = resolve_target(path_);
  target_ = t.path;
  if (t.write_through) {
    // O_NOCTTY: a terminal named by -o must not become our controlling terminal.
    const int fd = ::open(target_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0 || !(file_ = ::fdopen(fd, "wb"))) {
      const int err = errno;
      if (fd >= 0) ::close(fd);
      throw cannot_write(path_, err);
    }
    return;
  }
  temp_ = target_ + ".tmp-" + std::to_string(::getpid());
  // Registered before the file exists and unregistered only after it is gone (below): a signal at
  // any moment in between finds it in the registry.
  register_temp(temp_.c_str());
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_) {
    const int err = errno;
    unregister_temp(temp_.c_str());
    throw cannot_write(path_, err);
  }
}

void AtomicFile::check(const std::string& path) {
  const Target t = resolve_target(path);
  if (!t.write_through) {
    AtomicFile probe(path);  // created and removed again
    return;
  }
  if (::access(t.path.c_str(), W_OK) != 0) throw cannot_write(path, errno);
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (file_) std::fclose(file_);
  if (temp_.empty()) return;
  std::remove(temp_.c_str());
  unregister_temp(temp_.c_str());
}

void AtomicFile::commit() {
  const bool write_ok = std::fflush(file_) == 0 && !std::ferror(file_);
  const int write_err = errno;
  const bool close_ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!write_ok || !close_ok)
    throw RuntimeError("cannot write " + path_ + ": " + std::strerror(write_ok ? errno : write_err));
  if (temp_.empty()) {
    committed_ = true;
    return;
  }
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw RuntimeError("cannot rename " + temp_ + " to " + target_ + ": " + std::strerror(errno));
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
