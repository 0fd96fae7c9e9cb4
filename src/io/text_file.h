// Reading a whole input file (OBJ, scene JSON, rays and mesh CSV) into memory, safely: a stranger's
// path may name binary data, a device that never ends (/dev/zero, /dev/urandom) or a FIFO fed by
// `yes`. All of them end in a clear InputError instead of a hang or an out-of-memory kill.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rayvec {

// The largest input file read_text_file accepts, in bytes: RAYVEC_MAX_INPUT_MB megabytes (10^6
// bytes) from the environment when set to a positive integer, else 4096 MB. Inputs that big are
// far beyond any scene rayvec traces well (a 1M-triangle OBJ is about 60 MB).
std::size_t max_input_bytes();
// What is wrong with RAYVEC_MAX_INPUT_MB when it is set but not a whole number of megabytes from 1
// to 2^40 − 1 (the message to print; every command checks it before it starts), else nothing:
// max_input_bytes would take the default, against what the user asked.
std::optional<std::string> input_limit_problem();

// Whether RAYVEC_MAX_INPUT_MB sets the limit (set and well formed), rather than the default.
bool input_limit_from_environment();

// The whole file as text. Throws InputError(`path: cannot read: <reason>`) when it cannot be opened
// or read (missing file, a directory, no permission). A UTF-8 byte-order mark is dropped (editors
// on Windows write one; it would otherwise glue itself to the first keyword or number). Throws
// InputError for text that is not ASCII/UTF-8: `path: is UTF-16 text ...` for a UTF-16 byte-order
// mark, `path:line: contains a NUL byte ...` for binary data (or UTF-16/32 without a mark) — found
// while reading, so /dev/zero fails at once. A file (or stream) longer than max_input_bytes()
// throws `path: is larger than the N MB input limit ...` naming RAYVEC_MAX_INPUT_MB; a regular file
// is judged by its size before any byte is read.
// "-" reads standard input; messages then name it "stdin" (see text_name).
std::string read_text_file(const std::string& path);
// A whole input file's text, as read_text_file gives it (the same checks, messages and dropped
// UTF-8 byte-order mark), but a regular file of 1 MiB or more is mapped into memory read-only
// instead of copied: the text then lives in the kernel's page cache, with no fresh pages to clear
// and fill (a 39 MB OBJ: 38–60 ms read into a new buffer, 4 ms mapped). Should the file shrink
// while it is mapped (another program rewriting it), reading the lost pages would be a SIGBUS:
// that ends the process with `rayvec: <path> was truncated while it was being read` and exit
// status 1, never a crash. Move-only; the text is valid while the TextFile lives.
class TextFile {
 public:
  explicit TextFile(const std::string& path);
  ~TextFile();
  TextFile(TextFile&& other) noexcept;
  TextFile& operator=(TextFile&&) = delete;
  TextFile(const TextFile&) = delete;
  std::string_view text() const { return text_; }
  bool mapped() const { return map_ != nullptr; }

 private:
  void unmap();

  std::string owned_;
  void* map_ = nullptr;
  std::size_t map_size_ = 0;
  std::string_view text_;
};

// The name read_text_file's messages use for `path`: "stdin" for "-", else the path.
inline std::string text_name(const std::string& path) { return path == "-" ? "stdin" : path; }

// The line of `text` that starts at `pos`, without its end, and `pos` moved past that end. Lines end
// as tinyobjloader ends them — LF, CRLF or a lone CR (old Mac files) — so the OBJ and MTL readers'
// line numbers are the ones a user's editor shows. Call while pos < text.size().
inline std::string_view next_text_line(std::string_view text, std::size_t& pos) {
  std::size_t end = text.find_first_of("\r\n", pos);
  if (end == std::string_view::npos) end = text.size();
  const std::string_view line = text.substr(pos, end - pos);
  pos = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  return line;
}

}  // namespace rayvec
