#include "distributed/tile_dealer.h"

#include <algorithm>
#include <cstdint>

namespace rayvec {

TileDealer::TileDealer(Cluster& cluster, int tiles, int threads, std::function<void(double)> progress)
    : cluster_(cluster), tiles_(tiles), threads_(std::max(1, threads)), progress_(std::move(progress)) {}

TileRange TileDealer::take(int threads) {
  const int left = tiles_ - next_;
  // A quarter of a fair share of what is left, at least one tile per thread of the asking rank.
  const int guided = (left + 4 * cluster_.size() - 1) / (4 * cluster_.size());
  const TileRange r{next_, std::min(left, std::max(guided, std::max(1, threads)))};
  next_ += r.count;
  ranges_ += r.count > 0;
  return r;
}

void TileDealer::report(int finished) {
  finished_ += finished;
  if (progress_ && tiles_ > 0) progress_(double(finished_) / tiles_);
}

void TileDealer::answer(int rank) {
  int64_t request[2];  // tiles finished since the last request, the rank's threads
  cluster_.recv(rank, kTagTileRequest, request, sizeof request);
  report(int(request[0]));
  const TileRange r = take(int(request[1]));
  const int32_t reply[2] = {r.first, r.count};
  cluster_.send(rank, kTagTileReply, reply, sizeof reply);
  stopped_ += r.count == 0;
}

TileRange TileDealer::next(int finished) {
  if (cluster_.root()) {
    report(finished);
    return take(threads_);
  }
  const int64_t request[2] = {finished, threads_};
  cluster_.send(0, kTagTileRequest, request, sizeof request);
  int32_t reply[2];
  cluster_.recv(0, kTagTileReply, reply, sizeof reply);
  return {reply[0], reply[1]};
}

void TileDealer::serve() {
  int from = 0;
  while (cluster_.distributed() && cluster_.probe(Cluster::kAnySource, kTagTileRequest, false, &from))
    answer(from);
}

void TileDealer::serve_until_done() {
  int from = 0;
  while (stopped_ < cluster_.size() - 1) {
    cluster_.probe(Cluster::kAnySource, kTagTileRequest, true, &from);
    answer(from);
  }
}

}  // namespace rayvec
