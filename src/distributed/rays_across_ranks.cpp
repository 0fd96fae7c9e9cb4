#include "distributed/rays_across_ranks.h"

#include <chrono>
#include <type_traits>

#include "platform/stopwatch.h"

namespace rayvec {
namespace {

// Every rank's (rays, nanoseconds) to rank 0, into `loads`.
void gather_loads(Cluster& cluster, uint64_t rays, double seconds, RankLoads& loads) {
  std::vector<int64_t> mine(2 * std::size_t(cluster.size()), 0);
  mine[2 * cluster.rank()] = int64_t(rays);
  mine[2 * cluster.rank() + 1] = int64_t(seconds * 1e9);
  cluster.all_sum(mine);
  loads.ranks.clear();
  if (!cluster.root()) return;
  for (int r = 0; r < cluster.size(); ++r)
    loads.ranks.push_back({uint64_t(mine[2 * r]), 0, 0, double(mine[2 * r + 1]) * 1e-9});
}

// Rank 0 gets every rank's share of `answers` in rank order, i.e. input order.
template <class T>
void gather_in_order(Cluster& cluster, std::vector<T>& answers, RankLoads& loads) {
  const auto t = std::chrono::steady_clock::now();
  if (!cluster.root()) {
    cluster.send_vector(0, kTagResults, answers);
    answers.clear();
    return;
  }
  for (int r = 1; r < cluster.size(); ++r) {
    const std::vector<T> part = cluster.recv_vector<T>(r, kTagResults);
    answers.insert(answers.end(), part.begin(), part.end());
  }
  loads.gather_seconds = seconds_since(t);
}

// Rank 0 keeps its share of `rays` and sends the others theirs.
std::vector<Ray> scatter_rays(Cluster& cluster, const RayBatch& rays) {
  static_assert(std::is_trivially_copyable_v<Ray>);
  uint64_t n = rays.size();
  cluster.broadcast(&n, sizeof n);
  std::vector<Ray> share;
  if (!cluster.root()) return cluster.recv_vector<Ray>(0, kTagResults);
  for (int r = cluster.size() - 1; r >= 0; --r) {
    const auto [first, last] = share_of(n, r, cluster.size());
    share.clear();
    share.reserve(last - first);
    for (std::size_t i = first; i < last; ++i) share.push_back(rays[i]);
    if (r > 0) cluster.send_vector(r, kTagResults, share);
  }
  return share;
}

template <class T, class Trace>
void trace_across_ranks(Cluster& cluster, const RayBatch& rays, std::vector<T>& out, RankLoads& loads,
                        Trace trace) {
  if (!cluster.distributed()) {
    const auto t = std::chrono::steady_clock::now();
    out.resize(rays.size());
    trace(rays, out);
    loads.ranks = {{rays.size(), 0, 0, seconds_since(t)}};
    return;
  }
  const std::vector<Ray> share = scatter_rays(cluster, rays);
  const auto t = std::chrono::steady_clock::now();
  out.resize(share.size());
  trace(share, out);
  const double seconds = seconds_since(t);
  cluster.test_failure_point();
  gather_loads(cluster, share.size(), seconds, loads);
  gather_in_order(cluster, out, loads);
}

}  // namespace

std::pair<std::size_t, std::size_t> share_of(std::size_t n, int rank, int ranks) {
  const std::size_t base = n / std::size_t(ranks), extra = n % std::size_t(ranks), r = std::size_t(rank);
  const std::size_t first = r * base + std::min(r, extra);
  return {first, first + base + (r < extra ? 1 : 0)};
}

void trace_closest_across_ranks(Cluster& cluster, const Accelerator& accel, const RayBatch& rays,
                                std::vector<Hit>& hits, RankLoads& loads) {
  trace_across_ranks(cluster, rays, hits, loads,
                     [&](const auto& share, std::vector<Hit>& out) { trace_closest(accel, share, out); });
}

void trace_occluded_across_ranks(Cluster& cluster, const Accelerator& accel, const RayBatch& rays,
                                 std::vector<uint8_t>& occluded, RankLoads& loads) {
  trace_across_ranks(cluster, rays, occluded, loads, [&](const auto& share, std::vector<uint8_t>& out) {
    trace_occluded(accel, share, out);
  });
}

std::vector<Visibility> visibility_across_ranks(Cluster& cluster, const Accelerator& accel,
                                                const TriangleMesh& mesh, const std::vector<Vec3f>& verts,
                                                Vec3f origin, RankLoads& loads) {
  const auto t = std::chrono::steady_clock::now();
  if (!cluster.distributed()) {
    std::vector<Visibility> all = compute_visibility(accel, mesh, verts, origin);
    loads.ranks = {{verts.size(), 0, 0, seconds_since(t)}};
    return all;
  }
  cluster.begin_collective();
  const auto [first, last] = share_of(verts.size(), cluster.rank(), cluster.size());
  const std::vector<Vec3f> mine(verts.begin() + std::ptrdiff_t(first), verts.begin() + std::ptrdiff_t(last));
  std::vector<Visibility> answers = compute_visibility(accel, mesh, mine, origin);
  const double seconds = seconds_since(t);
  cluster.test_failure_point();
  gather_loads(cluster, mine.size(), seconds, loads);
  gather_in_order(cluster, answers, loads);
  return answers;
}

}  // namespace rayvec
