// RankLoads: how the work of a distributed command fell on its ranks, as rank 0 reports it with
// --stats (render) or on stderr (hits, visibility): rays and seconds per rank and the load
// imbalance.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rayvec {

struct RankLoad {
  uint64_t rays = 0;
  int tiles = 0, ranges = 0;  // render: tiles rendered, in how many ranges dealt
  double seconds = 0;         // the rank's working time (render: first range asked to last tile done)
};

struct RankLoads {
  std::vector<RankLoad> ranks;  // by rank; filled on rank 0 only
  double gather_seconds = 0;    // rank 0: receiving and placing the other ranks' results

  // Slowest rank's seconds over the mean (1 = perfectly balanced); 0 without ranks.
  double imbalance() const;
  // "ranks: 2; rays per rank: 1.2e+06, 1.1e+06; tiles per rank (in ranges): 310 in 9, 290 in 8
  //  rank seconds: 1.021, 1.013; load imbalance (slowest / mean): 1.004; gather 0.004 s" (tiles
  // only for a render), each line ending in a newline.
  std::string text() const;
};

}  // namespace rayvec
