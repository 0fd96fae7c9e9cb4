// TileDealer: hands out the tiles of a distributed render as they are wanted — a work queue kept by
// rank 0, which also renders. A rank asks for the next range of tiles when it has finished its last
// one; ranges shrink as the queue empties (guided self-scheduling, Polychronopoulos & Kuck 1987), so
// large ranges early keep the messages few and small ranges late keep the ranks finishing together.
// Which rank renders a tile never changes the image (render/tile_renderer.h).
#pragma once
#include <functional>

#include "distributed/cluster.h"

namespace rayvec {

struct TileRange {
  int first = 0, count = 0;  // count 0: no tiles left
};

class TileDealer {
 public:
  // `threads`: this rank's rendering threads (a range holds at least one tile per thread when the
  // queue has that many). `progress` (rank 0 only, may be empty): the finished fraction of all tiles.
  TileDealer(Cluster& cluster, int tiles, int threads, std::function<void(double)> progress = {});

  // The next range for this rank, reporting `finished` tiles done since the last call. Rank 0 takes
  // it from the queue; the others ask rank 0 and wait for the answer.
  TileRange next(int finished);
  // Rank 0, main thread only: answers the requests waiting now (call it often while rendering).
  void serve();
  // Rank 0: after its own last range, answers until every other rank has been told that the queue
  // is empty.
  void serve_until_done();

  int ranges_dealt() const { return ranges_; }

 private:
  TileRange take(int threads);
  void answer(int rank);
  void report(int finished);

  Cluster& cluster_;
  const int tiles_, threads_;
  std::function<void(double)> progress_;
  int next_ = 0, finished_ = 0, stopped_ = 0, ranges_ = 0;
};

}  // namespace rayvec
