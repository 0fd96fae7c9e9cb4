// Parsing a CSV text's lines in parallel: the text is cut at line ends into chunks of about
// `chunk_bytes`, each chunk's lines are parsed into a part of its own on one of the OpenMP threads,
// and the parts come back in the text's order. Line numbers are those of the whole text, and when
// lines fail the error of the first failing line is the one thrown — as a serial reader would.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>
#include <vector>

#include "io/csv_fields.h"

namespace rayvec {

// parse(part, line, line_number) for every line of `text` (LineCursor's lines: LF or CRLF ends),
// where the text's first line is number `first_line`; one Part per chunk, in order.
template <class Part, class Parse>
std::vector<Part> parse_csv_chunks(std::string_view text, std::size_t first_line, Parse parse,
                                   std::size_t chunk_bytes = kCsvChunkBytes) {
  std::vector<std::size_t> begin{0};  // chunk k: [begin[k], begin[k + 1]), each after a '\n'
  while (begin.back() < text.size()) {
    const std::size_t want = begin.back() + std::max<std::size_t>(chunk_bytes, 1);
    const std::size_t nl = want >= text.size() ? std::string_view::npos : text.find('\n', want - 1);
    begin.push_back(nl == std::string_view::npos ? text.size() : nl + 1);
  }
  const auto chunks = static_cast<std::int64_t>(begin.size()) - 1;
  std::vector<std::size_t> lines(std::size_t(std::max<std::int64_t>(chunks, 0)) + 1, 0);
  std::vector<Part> parts(lines.size() - 1);
  std::vector<std::exception_ptr> failed(parts.size());
#pragma omp parallel if (chunks > 1)
  {
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < chunks; ++k)
      lines[std::size_t(k) + 1] = std::size_t(std::count(text.begin() + std::ptrdiff_t(begin[k]),
                                                         text.begin() + std::ptrdiff_t(begin[k + 1]), '\n'));
#pragma omp single
    for (std::size_t k = 1; k < lines.size(); ++k) lines[k] += lines[k - 1];  // lines before chunk k
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t k = 0; k < chunks; ++k) {
      try {
        LineCursor cursor(text.substr(begin[k], begin[k + 1] - begin[k]));
        std::string_view line;
        while (cursor.next(line)) parse(parts[k], line, first_line + lines[k] + cursor.line_number() - 1);
      } catch (...) {
        failed[k] = std::current_exception();
      }
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  return parts;
}

}  // namespace rayvec
