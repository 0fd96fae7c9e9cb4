// AtomicFile: writes an output file under a temporary name in the same directory and renames it
// into place only on commit(), so an interrupted or failed run never leaves a partial file that
// looks complete. Destroying an uncommitted AtomicFile removes the temporary.
//
// What the path names decides how it is written (see docs/reliability.md, "Output targets"):
//   a regular file, or nothing yet      temporary + rename (the file is replaced whole or not at all)
//   a symbolic link                     the file it resolves to is written that way; the link stays
//   a FIFO or a character device        written through, never replaced (`-o /dev/null`, a named pipe)
//   a directory                         RuntimeError (exit status 1), as for any unwritable path
//   a dangling link, a socket,          InputError (exit status 2): rayvec never turns these into a
//   a block device                      regular file nor writes raw data onto a disk
#pragma once
#include <cstdio>
#include <string>

namespace rayvec {

class AtomicFile {
 public:
  // Opens "<target>.tmp-<pid>" for writing (or the FIFO/device itself); throws RuntimeError naming
  // the path when it cannot, InputError for a target rayvec refuses (see above).
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Checks, before any work, that `path` can be written: refused targets throw as the constructor
  // would; a regular target is probed by creating and removing its temporary. A FIFO is not opened
  // (that would wait for a reader, and closing it would end the reader's input).
  static void check(const std::string& path);

  std::FILE* stream() { return file_; }
  const std::string& temp_path() const { return temp_; }
  // Flushes, closes and renames onto the final path; throws RuntimeError on any failure.
  void commit();

 private:
  std::string path_, target_, temp_;  // temp_ is empty when writing through
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

// Removes every temporary that an AtomicFile of this process still has open (for signal handlers:
// async-signal-safe, uses only unlink).
void remove_open_temporaries_on_signal();

}  // namespace rayvec
