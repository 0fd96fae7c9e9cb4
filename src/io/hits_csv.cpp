#include "io/hits_csv.h"

#include <omp.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

#include "io/output_sink.h"

namespace rayvec {
namespace {

constexpr std::size_t kBlock = 1 << 15;  // rays formatted per task

char* put(char* p, float x) { return std::to_chars(p, p + 32, x).ptr; }
char* put(char* p, int64_t x) { return std::to_chars(p, p + 24, x).ptr; }

// Formats rows [0, n) with row(i, buffer) -> end, kBlock rows per task, and writes the blocks in
// order. At most one block per thread is held at a time beyond the one being written.
template <typename Row>
void write_rows(OutputSink& out, const char* header, std::size_t n, std::size_t max_row, Row row) {
  out.write(header, std::char_traits<char>::length(header));
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  const std::size_t group = static_cast<std::size_t>(omp_get_max_threads());
  std::vector<std::string> text(group);
  for (std::size_t g0 = 0; g0 < blocks; g0 += group) {
    const auto count = static_cast<std::int64_t>(std::min(group, blocks - g0));
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t b = 0; b < count; ++b) {
      const std::size_t begin = (g0 + b) * kBlock, end = std::min(n, begin + kBlock);
      std::string& s = text[b];
      s.resize((end - begin) * max_row);
      char* p = s.data();
      for (std::size_t i = begin; i < end; ++i) p = row(i, p);
      s.resize(p - s.data());
    }
    for (std::int64_t b = 0; b < count; ++b) out.write(text[b].data(), text[b].size());
  }
}

}  // namespace

void write_hits_csv(OutputSink& out, std::span<const Hit> hits) {
  // ray (20) + tri (11) + three floats (<= 15 each) + separators
  write_rows(out, "ray,tri,t,u,v\n", hits.size(), 96, [&](std::size_t i, char* p) {
    const Hit& h = hits[i];
    p = put(p, static_cast<int64_t>(i));
    *p++ = ',';
    p = put(p, static_cast<int64_t>(h.tri));
    *p++ = ',';
    p = put(p, h.t);
    *p++ = ',';
    p = put(p, h.hit() ? h.u : 0.0f);
    *p++ = ',';
    p = put(p, h.hit() ? h.v : 0.0f);
    *p++ = '\n';
    return p;
  });
}

void write_any_hits_csv(OutputSink& out, std::span<const uint8_t> occluded) {
  write_rows(out, "ray,hit\n", occluded.size(), 32, [&](std::size_t i, char* p) {
    p = put(p, static_cast<int64_t>(i));
    *p++ = ',';
    *p++ = occluded[i] ? '1' : '0';
    *p++ = '\n';
    return p;
  });
}

}  // namespace rayvec
