#include "distributed/rank_loads.h"

#include <algorithm>
#include <cstdio>

namespace rayvec {

double RankLoads::imbalance() const {
  double slowest = 0, sum = 0;
  for (const RankLoad& r : ranks) {
    slowest = std::max(slowest, r.seconds);
    sum += r.seconds;
  }
  return sum > 0 ? slowest / (sum / double(ranks.size())) : 0.0;
}

std::string RankLoads::text() const {
  std::string rays, tiles, seconds;
  char buf[64];
  bool any_tiles = false;
  for (const RankLoad& r : ranks) {
    std::snprintf(buf, sizeof buf, "%s%.4g", rays.empty() ? "" : ", ", double(r.rays));
    rays += buf;
    tiles += (tiles.empty() ? "" : ", ") + std::to_string(r.tiles) + " in " + std::to_string(r.ranges);
    any_tiles = any_tiles || r.tiles > 0;
    std::snprintf(buf, sizeof buf, "%s%.3f", seconds.empty() ? "" : ", ", r.seconds);
    seconds += buf;
  }
  std::string s = "ranks: " + std::to_string(ranks.size()) + "; rays per rank: " + rays;
  if (any_tiles) s += "; tiles per rank (in ranges): " + tiles;
  std::snprintf(buf, sizeof buf, "%.3f; gather %.3f s\n", imbalance(), gather_seconds);
  return s + "\nrank seconds: " + seconds + "; load imbalance (slowest / mean): " + buf;
}

}  // namespace rayvec
