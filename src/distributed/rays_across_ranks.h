// Ray queries shared by the ranks of a cluster (`hits`, `visibility`): each rank traces one
// contiguous share of the rays with all its threads and rank 0 gathers the answers in input order.
// Every ray's answer depends on that ray alone (accel/accelerator.h), so they equal one process's.
// Shares are static: rays of one query cost alike, unlike the tiles of a render.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "accel/accelerator.h"
#include "accel/visibility.h"
#include "distributed/cluster.h"
#include "distributed/rank_loads.h"

namespace rayvec {

// Rank `rank`'s share [first, last) of n items: contiguous, in rank order, sizes differing by at
// most one.
std::pair<std::size_t, std::size_t> share_of(std::size_t n, int rank, int ranks);

// `rays` is read on rank 0 (ignored elsewhere): rank 0 sends each rank its share, and gets every
// answer back in `hits` / `occluded` (left empty on the other ranks). A cluster of one traces them
// itself.
void trace_closest_across_ranks(Cluster& cluster, const Accelerator& accel, const RayBatch& rays,
                                std::vector<Hit>& hits, RankLoads& loads);
void trace_occluded_across_ranks(Cluster& cluster, const Accelerator& accel, const RayBatch& rays,
                                 std::vector<uint8_t>& occluded, RankLoads& loads);

// compute_visibility over every rank: each has `verts` and `mesh` (replicated) and computes its
// share; rank 0 returns every answer, the others an empty vector.
std::vector<Visibility> visibility_across_ranks(Cluster& cluster, const Accelerator& accel,
                                                const TriangleMesh& mesh, const std::vector<Vec3f>& verts,
                                                Vec3f origin, RankLoads& loads);

}  // namespace rayvec
