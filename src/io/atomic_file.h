// AtomicFile: writes an output file under a temporary name in the same directory and renames it
// into place only on commit(), so an interrupted or failed run never leaves a partial file that
// looks complete. Destroying an uncommitted AtomicFile removes the temporary.
#pragma once
#include <cstdio>
#include <string>

namespace rayvec {

class AtomicFile {
 public:
  // Opens "<path>.tmp-<pid>" for writing; throws RuntimeError naming the path when it cannot.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* stream() { return file_; }
  const std::string& temp_path() const { return temp_; }
  // Flushes, closes and renames onto the final path; throws RuntimeError on any failure.
  void commit();

 private:
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

// Removes every temporary that an AtomicFile of this process still has open (for signal handlers:
// async-signal-safe, uses only unlink).
void remove_open_temporaries_on_signal();

}  // namespace rayvec
