// Small pieces shared by rayvec's CSV readers (rays, verts, faces): line
// iteration with line numbers, and strict number fields through std::from_chars. Every failure is an
// InputError `file:line: what is wrong`.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace rayvec {

// `text` as it may appear inside a message: bytes outside printable ASCII shown as \xNN, and cut
// to its first 40 bytes followed by "..." so that a megabyte-long token gives a one-line message.
std::string printable(std::string_view text);

// The size of the chunks the CSV readers parse in parallel (csv_chunks.h).
inline constexpr std::size_t kCsvChunkBytes = std::size_t(1) << 20;

// Walks `text` line by line. Accepts LF and CRLF line ends and a last line without one.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  // The next line without its line end; false at the end of the text.
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_; }  // 1-based number of the line last returned
  std::size_t position() const { return pos_; }      // offset of the next line (past the end at the end)

 private:
  std::string_view text_;
  std::size_t pos_ = 0, line_ = 0;
};

// True for a line with only spaces/tabs, or whose first non-blank character is '#'.
bool is_blank_or_comment(std::string_view line);

// Number of comma-separated fields in `line` (commas + 1).
std::size_t count_fields(std::string_view line);

// Where the error messages point: the file and the line being parsed.
struct CsvPlace {
  const std::string& file;
  std::size_t line;
};

// Parses the comma-separated fields of `line` into out[0..n) (n must equal count_fields(line)).
// Spaces and tabs around a field are ignored; a leading '+' is accepted; `nan`, `inf`, `infinity`
// (any case, optional sign) give non-finite values, which the caller judges. A field that is empty
// or not entirely a number throws `file:line: field K 'text' is not a number`; a finite number too
// large for the type throws `... is out of range`. Underflow gives 0 or a subnormal.
// InputError when `line` holds a CR before its end: a file with lone-CR line ends (classic Mac OS
// text) reads as one long line, and "found 11 fields" would not say why. Called on the error path.
void check_no_inner_cr(std::string_view line, const CsvPlace& where);

void parse_fields(std::string_view line, float* out, std::size_t n, const CsvPlace& where);
void parse_fields(std::string_view line, double* out, std::size_t n, const CsvPlace& where);

}  // namespace rayvec
