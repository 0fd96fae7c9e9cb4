// Parts of `rayvec bench paper`'s report (src/app/cmd_bench_paper.cpp): the hits of each Table 1
// row with their checksum, and across ranks each rank's share, times and load imbalance, as text and
// as JSON.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bench/paper_bench.h"

namespace rayvec {

std::string join_counts(const std::vector<uint64_t>& v);  // "1, 2, 3"
std::string join_seconds(const std::vector<double>& v);   // "0.1000, 0.2000"
// Slowest over mean (1 = balanced); 0 without time.
double slowest_over_mean(const std::vector<double>& seconds);

// Per row: how many rays hit and the checksum of the hits (bench/paper_shares.h), equal in one
// process and across any number of ranks; across ranks, each rank's share and times.
void print_hits(const std::vector<Table1Result>& rows, int ranks);

// Across ranks, the row's JSON "shares" member (with its leading comma).
void print_json_shares(const Table1Result& r);

}  // namespace rayvec
