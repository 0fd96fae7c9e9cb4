#include "distributed/render_across_ranks.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "distributed/tile_dealer.h"
#include "platform/stopwatch.h"
#include "render/camera_rays.h"
#include "render/render_budget.h"
#include "render/tile_renderer.h"

namespace rayvec {
namespace {

// What a rank sends rank 0 besides its pixels: its counters, then its ranges as (first, count).
enum Field {
  kPrimary,
  kPrimaryHits,
  kShadow,
  kReflection,
  kRefraction,
  kTiles,
  kSeconds,
  kPrimaryThread,
  kShadingThread,
  kThreads,
  kFields
};

constexpr double kNanos = 1e9;

struct RankWork {
  std::vector<int64_t> header;  // kFields counters, then the ranges
  std::vector<float> pixels;    // the tiles of the ranges in order, each rect.pixels() × channels
};

// Asks for ranges until the queue is empty and renders each with all threads; rank 0 answers the
// other ranks' requests between its own tiles.
RankWork render_my_tiles(Cluster& cluster, TileDealer& dealer, const TileGrid& grid, int nc,
                         const Scene& scene, const Accelerator& accel, const RenderSettings& settings) {
  const CameraRays camera(scene.camera);
  const TriangleNormals normals = TriangleNormals::for_render(scene, settings.spp, available_memory_bytes());
  const int threads = std::max(1, omp_get_max_threads());
  std::vector<std::unique_ptr<TileRenderer>> renderers(static_cast<std::size_t>(threads));
  RankWork work;
  work.header.assign(kFields, 0);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::size_t> offset;
  for (int finished = 0;;) {
    const TileRange r = dealer.next(finished);
    if (r.count == 0) break;
    offset.assign(std::size_t(r.count) + 1, work.pixels.size());
    for (int i = 0; i < r.count; ++i)
      offset[i + 1] = offset[i] + std::size_t(grid.rect(r.first + i).pixels()) * nc;
    work.pixels.resize(offset.back());
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::min(threads, r.count))
    for (int i = 0; i < r.count; ++i) {
      const int t = omp_get_thread_num();
      if (!renderers[t])
        renderers[t] = std::make_unique<TileRenderer>(scene, accel, settings, camera, &normals);
      renderers[t]->render(grid.rect(r.first + i), work.pixels.data() + offset[i]);
      if (t == 0 && cluster.root()) dealer.serve();  // the main thread: MPI_THREAD_FUNNELED
    }
    work.header.insert(work.header.end(), {r.first, r.count});
    work.header[kTiles] += r.count;
    finished = r.count;
    if (work.header.size() == kFields + 2) cluster.test_failure_point();
  }
  work.header[kSeconds] = int64_t(seconds_since(t0) * kNanos);
  work.header[kThreads] = threads;
  for (const auto& r : renderers) {
    if (!r) continue;
    work.header[kPrimary] += int64_t(r->rays.primary);
    work.header[kPrimaryHits] += int64_t(r->rays.primary_hits);
    work.header[kShadow] += int64_t(r->rays.shadow);
    work.header[kReflection] += int64_t(r->rays.reflection);
    work.header[kRefraction] += int64_t(r->rays.refraction);
    work.header[kPrimaryThread] += int64_t(r->primary_seconds * kNanos);
    work.header[kShadingThread] += int64_t(r->shading_seconds * kNanos);
  }
  return work;
}

// Rank 0: one rank's tiles into the image, and its counters into the statistics.
void place(const RankWork& work, const TileGrid& grid, Image& image, RenderStats& stats, RankLoads& loads) {
  const std::vector<int64_t>& h = work.header;
  const int nc = image.nchannels();
  std::size_t at = 0;
  for (std::size_t k = kFields; k + 1 < h.size(); k += 2)
    for (int64_t tile = h[k]; tile < h[k] + h[k + 1]; ++tile) {
      const TileRect rect = grid.rect(int(tile));
      for (int y = rect.y0; y < rect.y1; ++y, at += std::size_t(rect.width()) * nc)
        std::copy_n(work.pixels.data() + at, std::size_t(rect.width()) * nc, &image.at(rect.x0, y, 0));
    }
  const RayCounts rays{uint64_t(h[kPrimary]), uint64_t(h[kShadow]), uint64_t(h[kReflection]),
                       uint64_t(h[kRefraction]), uint64_t(h[kPrimaryHits])};
  stats.rays += rays;
  stats.primary_thread_seconds += double(h[kPrimaryThread]) / kNanos;
  stats.shading_thread_seconds += double(h[kShadingThread]) / kNanos;
  stats.threads += int(h[kThreads]);
  loads.ranks.push_back(
      {rays.total(), int(h[kTiles]), int(h.size() - kFields) / 2, double(h[kSeconds]) / kNanos});
}

}  // namespace

Image render_across_ranks(Cluster& cluster, const Scene& scene, const Accelerator& accel,
                          const RenderSettings& settings, RenderStats& stats, RankLoads& loads,
                          const std::function<void(double)>& progress) {
  const TileGrid grid(scene.camera.width, scene.camera.height);
  if (!cluster.distributed()) {
    Image image = render(scene, accel, settings, stats, progress);
    loads.ranks = {{stats.rays.total(), grid.count(), 1, stats.render_seconds}};
    return image;
  }
  const std::vector<std::string> channels = render_channel_names(settings.aov);
  const int nc = int(channels.size());
  check_render_budget(scene, nc, available_memory_bytes());
  cluster.begin_collective();  // a rank that failed so far stops every rank here, not mid-render

  const auto t0 = std::chrono::steady_clock::now();
  TileDealer dealer(cluster, grid.count(), omp_get_max_threads(),
                    cluster.root() ? progress : std::function<void(double)>{});
  RankWork mine = render_my_tiles(cluster, dealer, grid, nc, scene, accel, settings);
  if (!cluster.root()) {
    cluster.send_vector(0, kTagResults, mine.header);
    cluster.send_vector(0, kTagResults, mine.pixels);
    return {};
  }
  dealer.serve_until_done();
  stats.render_seconds = seconds_since(t0);

  const auto tg = std::chrono::steady_clock::now();
  Image image(grid.width, grid.height, channels);
  stats.rays = {};
  stats.primary_thread_seconds = stats.shading_thread_seconds = 0;
  stats.threads = 0;
  loads.ranks.clear();
  place(mine, grid, image, stats, loads);
  mine = {};
  for (int rank = 1; rank < cluster.size(); ++rank) {
    RankWork work;
    work.header = cluster.recv_vector<int64_t>(rank, kTagResults);
    work.pixels = cluster.recv_vector<float>(rank, kTagResults);
    place(work, grid, image, stats, loads);
  }
  loads.gather_seconds = seconds_since(tg);
  if (progress) progress(1.0);
  return image;
}

}  // namespace rayvec
