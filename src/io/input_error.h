// The two kinds of failure every command reports (see docs: exit statuses).
//   InputError   — the user's input or usage is wrong: exit status 2. Message: `file:line: what is wrong`.
//   RuntimeError — the input was fine but the work failed (I/O, resources): exit status 1.
//   ReportedFailure — either of them, already reported by another rank of a distributed run.
#pragma once
#include <stdexcept>
#include <string>

namespace rayvec {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
  // `file:line: message` (line 0 means the whole file: `file: message`).
  InputError(const std::string& file, std::size_t line, const std::string& message)
      : std::runtime_error(place(file, line) + message) {}

 private:
  // Appended piece by piece: g++ 12 warns falsely (-Wrestrict, its bug 105651) on `":" + string`.
  static std::string place(const std::string& file, std::size_t line) {
    std::string s = file;
    if (line) {
      s += ':';
      s += std::to_string(line);
    }
    s += ": ";
    return s;
  }
};

struct RuntimeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A failure whose message another process has printed (a distributed run prints one rank's message
// for all): the command ends with `status` and prints nothing.
struct ReportedFailure {
  int status;
};

}  // namespace rayvec
