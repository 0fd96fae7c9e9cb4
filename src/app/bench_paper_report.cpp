#include "app/bench_paper_report.h"

#include <algorithm>
#include <cstdio>
#include <type_traits>
#include <utility>

#include "bench/paper_shares.h"

namespace rayvec {

std::string join_counts(const std::vector<uint64_t>& v) {
  std::string s;
  for (uint64_t x : v) {
    if (!s.empty()) s += ", ";
    s += std::to_string(x);
  }
  return s;
}

std::string join_seconds(const std::vector<double>& v) {
  std::string s;
  char buf[32];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, "%s%.4f", s.empty() ? "" : ", ", x);
    s += buf;
  }
  return s;
}

double slowest_over_mean(const std::vector<double>& seconds) {
  double slowest = 0, sum = 0;
  for (double x : seconds) slowest = std::max(slowest, x), sum += x;
  return sum > 0 ? slowest / (sum / double(seconds.size())) : 0.0;
}

namespace {

// A JSON list of one number per rank: counts exactly, other values to 6 digits.
template <class Get>
std::string per_rank(const std::vector<Table1Share>& shares, Get get) {
  std::string s = "[";
  char buf[32];
  for (const Table1Share& sh : shares) {
    const auto value = get(sh);
    if (s.size() > 1) s += ',';
    if constexpr (std::is_integral_v<decltype(value)>)
      s += std::to_string(value);
    else {
      std::snprintf(buf, sizeof buf, "%.6g", double(value));
      s += buf;
    }
  }
  return s + "]";
}

}  // namespace

void print_hits(const std::vector<Table1Result>& rows, int ranks) {
  std::printf(
      "\nHits of vec-paper in input order (checksum: sum of (ray + 1) * (bits of t << 32 | triangle + 1) "
      "mod 2^64)\n");
  std::printf("%-6s %9s %9s %18s\n", "model", "rays", "hits", "checksum");
  for (const Table1Result& r : rows)
    std::printf("%-6s %9llu %9llu 0x%016llx\n", r.model.name, (unsigned long long)r.rays(),
                (unsigned long long)r.hits, (unsigned long long)r.checksum);
  if (ranks <= 1) return;
  std::printf(
      "\nAcross %d ranks: rays per rank; per column each rank's seconds (load imbalance, slowest / "
      "mean); the gather; rays rank 0 traced again and how many differ from the gathered hits\n",
      ranks);
  for (const Table1Result& r : rows) {
    std::vector<uint64_t> rays;
    for (const Table1Share& sh : r.shares) rays.push_back(sh.rays());
    std::printf("%-6s rays %s", r.model.name, join_counts(rays).c_str());
    const std::pair<const char*, Timing Table1Share::*> columns[] = {{"original", &Table1Share::original},
                                                                     {"optimized", &Table1Share::optimized},
                                                                     {"vec-paper", &Table1Share::vec_paper},
                                                                     {"vec-mt", &Table1Share::vec_mt}};
    for (const auto& [name, column] : columns) {
      if (!r.baselines && (column == &Table1Share::original || column == &Table1Share::optimized)) continue;
      std::vector<double> seconds;
      for (const Table1Share& sh : r.shares) seconds.push_back((sh.*column).seconds);
      std::printf(" | %s %s (%.3f)", name, join_seconds(seconds).c_str(), share_imbalance(r.shares, column));
    }
    std::printf(" | gather %.3f s | traced again %llu, %llu differ\n", r.gather_seconds,
                (unsigned long long)r.checked_rays, (unsigned long long)r.rank_differences);
  }
}

// Across ranks, a row's "shares": each rank's first ray, rays, checks, and per column its seconds,
// repeats and probes (lists by rank) and the column's load imbalance; the gather and rank 0's second
// look at the hits.
void print_json_shares(const Table1Result& r) {
  const std::vector<Table1Share>& sh = r.shares;
  std::printf(",\"shares\":{\"first\":%s,\"rays\":%s,\"mismatches\":%s,\"mt_differences\":%s",
              per_rank(sh, [](const Table1Share& s) { return s.first; }).c_str(),
              per_rank(sh, [](const Table1Share& s) { return s.rays(); }).c_str(),
              per_rank(sh, [](const Table1Share& s) { return s.mismatches; }).c_str(),
              per_rank(sh, [](const Table1Share& s) { return s.mt_differences; }).c_str());
  const std::pair<const char*, Timing Table1Share::*> columns[] = {
      {"vectorized_paper", &Table1Share::vec_paper},
      {"vectorized_mt", &Table1Share::vec_mt},
      {"original", &Table1Share::original},
      {"optimized", &Table1Share::optimized}};
  for (int c = 0; c < (r.baselines ? 4 : 2); ++c) {
    const auto column = columns[c].second;
    std::printf(
        ",\"%s\":{\"seconds\":%s,\"repeats\":%s,\"clock_ghz\":%s,\"fma_per_cycle\":%s,"
        "\"imbalance\":%.4g}",
        columns[c].first, per_rank(sh, [&](const Table1Share& s) { return (s.*column).seconds; }).c_str(),
        per_rank(sh, [&](const Table1Share& s) { return (s.*column).repeats; }).c_str(),
        per_rank(sh, [&](const Table1Share& s) { return (s.*column).ghz; }).c_str(),
        per_rank(sh, [&](const Table1Share& s) { return (s.*column).fma_per_cycle; }).c_str(),
        share_imbalance(sh, column));
  }
  std::printf(",\"gather_seconds\":%.6g,\"checked_rays\":%llu,\"rank_differences\":%llu}", r.gather_seconds,
              (unsigned long long)r.checked_rays, (unsigned long long)r.rank_differences);
}

}  // namespace rayvec
