// A render shared by the ranks of a cluster: every rank has loaded the same scene and built the same
// accelerator (replicated, docs/distributed.md#memory); rank 0 deals the tiles (TileDealer), each
// rank renders the tiles it is dealt with all its OpenMP threads, and rank 0 gathers them into the
// image. The image is bit-identical to render()'s, whatever the number of ranks and the dealing.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "distributed/cluster.h"
#include "distributed/rank_loads.h"
#include "render/renderer.h"

namespace rayvec {

// render() across the ranks of `cluster` (render() itself for a cluster of one). Rank 0 returns the
// image and fills `stats` as render() does, summed over the ranks (threads: over every rank), and
// `loads`; the other ranks return an empty image. `progress` is called on rank 0 with the
// fraction of all tiles finished.
Image render_across_ranks(Cluster& cluster, const Scene& scene, const Accelerator& accel,
                          const RenderSettings& settings, RenderStats& stats, RankLoads& loads,
                          const std::function<void(double)>& progress = {});

}  // namespace rayvec
