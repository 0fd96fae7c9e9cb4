// `bench paper` split into shares of rays (one per rank under mpirun, docs/distributed.md): how the
// shares of a Table 1 row make the row, and how rank 0 checks that the hits it gathered are the ones
// a single process computes. Pure computation; the messages are in distributed/paper_across_ranks.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "bench/paper_bench.h"
#include "rays/ray.h"

namespace rayvec {

// Whether two closest hits are the same: id, and t, u, v bit for bit on a hit.
bool same_hit(const Hit& a, const Hit& b);

// Σ (i + 1)·key_i mod 2^64 over the rays i = first_ray, first_ray + 1, ... of `hits`, where
// key_i = (bits of t_i) << 32 | (triangle id_i + 1): a miss adds (bits of +inf) << 32 times (i + 1).
// The same for any split of the rays into shares, each summed with its own first_ray.
uint64_t hits_checksum(std::span<const Hit> hits, uint64_t first_ray = 0);

// The row made of its shares (in rank order, covering the rays without gaps) and the gathered
// vectorized `paper` hits of all the rays in input order: each column's seconds are the slowest
// share's, its repeats the fewest, its clock and FMA probes the mean of the shares'; mismatches and
// mt differences are summed; hits and checksum are counted on `hits`.
Table1Result combine_table1_shares(const PaperModel& model, uint32_t side, bool baselines,
                                   std::vector<Table1Share> shares, std::span<const Hit> hits);

// Slowest share's seconds in `column` over the mean of the shares' (1 = balanced; 0 without time).
double share_imbalance(const std::vector<Table1Share>& shares, Timing Table1Share::*column);

// The rays rank 0 traces again after a gather: every `shares.size()`-th ray (0, N, 2N, ...: about
// one share's worth, spread over every share) and the first and last ray of each share, where an
// off-by-one in the split or the gather would show. Sorted, without repeats.
std::vector<uint64_t> check_sample(const std::vector<Table1Share>& shares);

// How many of the `sample` rays of the row's scene have a vectorized `paper` hit (on this process,
// with `isa`) that differs from gathered[ray].
uint64_t retrace_differences(const PaperModel& model, uint32_t side, Isa isa,
                             std::span<const uint64_t> sample, std::span<const Hit> gathered);

}  // namespace rayvec
