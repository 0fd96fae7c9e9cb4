#include "io/csv_fields.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <system_error>

#include "io/input_error.h"

namespace rayvec {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

[[noreturn]] void bad_field(std::string_view field, std::size_t k, const CsvPlace& where, const char* what) {
  throw InputError(where.file, where.line,
                   "field " + std::to_string(k + 1) + " '" + printable(field) + "' " + what);
}

// A finite value beyond the float/double range parses as out_of_range in from_chars; so does an
// underflow. strtod tells them apart (HUGE_VAL vs 0/subnormal); it is the rare path only.
double parse_out_of_range(std::string_view field) {
  const std::string copy(field);
  return std::strtod(copy.c_str(), nullptr);
}

template <typename T>
void parse_fields_as(std::string_view line, T* out, std::size_t n, const CsvPlace& where) {
  std::size_t k = 0;
  while (k < n) {
    const std::size_t comma = line.find(',');
    const std::string_view raw = line.substr(0, comma);
    line = comma == std::string_view::npos ? std::string_view() : line.substr(comma + 1);
    std::string_view field = trim(raw);
    if (field.empty()) bad_field(field, k, where, "is empty (expected a number)");
    // from_chars rejects a leading '+', which CSV writers sometimes emit.
    std::string_view digits = field;
    if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+')
      digits.remove_prefix(1);
    T value{};
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
      bad_field(field, k, where, "is not a number");
    if (ec == std::errc::result_out_of_range) {
      const double wide = parse_out_of_range(digits);
      if (std::isinf(wide) || std::isinf(static_cast<T>(wide))) bad_field(field, k, where, "is out of range");
      value = static_cast<T>(wide);
    }
    out[k++] = value;
  }
}

}  // namespace

std::string printable(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    }
  }
  if (text.size() > kMax) out += "...";
  return out;
}

bool LineCursor::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end + 1;
  ++line_;
  return true;
}

bool is_blank_or_comment(std::string_view line) {
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == '\r') continue;
    return c == '#';
  }
  return true;
}

std::size_t count_fields(std::string_view line) {
  std::size_t n = 1;
  for (char c : line) n += c == ',';
  return n;
}

void parse_fields(std::string_view line, float* out, std::size_t n, const CsvPlace& where) {
  parse_fields_as(line, out, n, where);
}

void parse_fields(std::string_view line, double* out, std::size_t n, const CsvPlace& where) {
  parse_fields_as(line, out, n, where);
}

void check_no_inner_cr(std::string_view line, const CsvPlace& where) {
  const std::size_t cr = line.find('\r');
  if (cr != std::string_view::npos && cr + 1 < line.size())
    throw InputError(where.file, where.line,
                     "has a carriage return (CR) inside a line: lone-CR line ends (classic Mac OS text) "
                     "are not read; convert the file to LF or CRLF line ends (e.g. tr '\\r' '\\n')");
}

}  // namespace rayvec
