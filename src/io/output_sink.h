// OutputSink: where a command writes its result — standard output, or a file through AtomicFile
// (temporary name, renamed on commit) so that a failed run never leaves a partial file.
#pragma once
#include <cstdio>
#include <memory>
#include <string>

#include "io/atomic_file.h"

namespace rayvec {

class OutputSink {
 public:
  // path "" or "-": standard output. Otherwise opens the temporary (RuntimeError when it cannot:
  // exit status 1, e.g. for a directory that does not exist).
  explicit OutputSink(const std::string& path);

  std::FILE* stream() { return file_ ? file_->stream() : stdout; }
  bool is_stdout() const { return !file_; }
  // Writes `n` bytes; RuntimeError on failure (disk full, closed pipe).
  void write(const char* data, std::size_t n);
  // Flushes standard output, or renames the file into place. RuntimeError on failure.
  void commit();

 private:
  std::string path_;
  std::unique_ptr<AtomicFile> file_;
};

}  // namespace rayvec
