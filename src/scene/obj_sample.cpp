#include "scene/obj_sample.h"

#include <algorithm>

namespace rayvec {
namespace {

constexpr std::size_t kWindows = 32, kWindow = 4096;
// Parse cost of a byte of a face line against one of any other line: faces write 40 bytes of arrays
// per ~24 bytes of text, vertices 12 per ~26, and a later piece's arrays are written twice (its own,
// then its place in the joined ones). Balances the threads' clocks on the 1M-triangle sphere.
constexpr double kFaceCost = 1.7;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

ObjSample::ObjSample(std::string_view text) : text_(text) {
  const bool whole = text.size() <= kWindows * kWindow;
  const std::size_t step = whole ? text.size() : text.size() / kWindows;
  for (std::size_t at = 0; at < text.size(); at += step) {
    Segment s;
    s.begin = at;
    s.end = whole || at + 2 * step > text.size() ? text.size() : at + step;
    std::string_view window = text.substr(at, whole ? text.size() : kWindow);
    if (at > 0) {  // from the first line start in the window
      const std::size_t lf = window.find('\n');
      window.remove_prefix(lf == std::string_view::npos ? window.size() : lf + 1);
    }
    for (std::size_t lf; (lf = window.find('\n')) != std::string_view::npos; window.remove_prefix(lf + 1)) {
      const std::string_view line = window.substr(0, lf);
      const double bytes = static_cast<double>(lf + 1);
      s.covered += bytes;
      s.cost += bytes;
      if (line.rfind("vn ", 0) == 0) ++s.normals;
      if (line.rfind("v ", 0) == 0) ++s.positions;
      if (line.rfind("vt ", 0) == 0) ++s.texcoords;
      if (line.rfind("f ", 0) == 0) {
        std::size_t corners = 0;
        for (std::size_t i = 1; i < line.size(); ++i) corners += is_blank(line[i - 1]) && !is_blank(line[i]);
        s.triangles += corners > 2 ? static_cast<double>(corners - 2) : 1;
        s.cost += (kFaceCost - 1) * bytes;
      }
    }
    segments_.push_back(s);
    if (s.end == text.size()) break;
  }
}

ObjCounts ObjSample::before(std::size_t offset) const {
  double n[4] = {0, 0, 0, 0};
  for (const Segment& s : segments_) {
    if (s.covered == 0 || offset <= s.begin) continue;
    const double share = static_cast<double>(std::min(offset, s.end) - s.begin) / s.covered;
    n[0] += s.positions * share;
    n[1] += s.normals * share;
    n[2] += s.texcoords * share;
    n[3] += s.triangles * share;
  }
  const auto count = [](double x) { return static_cast<std::size_t>(x + 0.5); };
  return {count(n[0]), count(n[1]), count(n[2]), count(n[3])};
}

ObjCounts ObjSample::capacity() const {
  const ObjCounts n = before(text_.size());
  const auto room = [](std::size_t count) { return count + count / 5 + 16; };
  return {room(n.positions), room(n.normals), room(n.texcoords), room(n.triangles)};
}

// A segment whose window held no whole line (one line longer than the window) costs 1 per byte.
double ObjSample::cost_before(std::size_t offset) const {
  double cost = 0;
  for (const Segment& s : segments_) {
    if (offset <= s.begin) break;
    const double bytes = static_cast<double>(std::min(offset, s.end) - s.begin);
    cost += s.covered == 0 ? bytes : bytes * s.cost / s.covered;
  }
  return cost;
}

std::vector<std::string_view> ObjSample::split(int pieces) const {
  std::vector<std::string_view> out;
  const double total = cost_before(text_.size());
  std::size_t start = 0;
  for (int i = 1; i < pieces && start < text_.size(); ++i) {
    // the first byte where the cost before it reaches i / pieces of the total, by bisection
    const double goal = total * i / pieces;
    std::size_t lo = start, hi = text_.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (cost_before(mid) < goal)
        lo = mid + 1;
      else
        hi = mid;
    }
    const std::size_t lf = text_.find('\n', lo);
    const std::size_t cut = lf == std::string_view::npos ? text_.size() : lf + 1;
    out.push_back(text_.substr(start, cut - start));
    start = cut;
  }
  if (start < text_.size() || out.empty()) out.push_back(text_.substr(start));
  return out;
}

}  // namespace rayvec
