#include "bench/rays_bench.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>

#include "bench/median.h"

namespace rayvec {
namespace {

constexpr std::size_t kChunk = 256;     // rays per OpenMP work item (single rays)
constexpr std::size_t kTileChunk = 16;  // tiles per work item (packets)

// With one thread the OpenMP loops run on the calling thread, so its CPU time is the work alone —
// unlike the wall clock it does not count the time other processes hold the core.
double clock_seconds(bool thread_cpu) {
  if (thread_cpu) {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// trace(k) runs tracer k once. Returns the median time of each tracer over `repeats` interleaved runs.
template <class F>
std::vector<double> median_seconds(F&& trace, std::size_t tracers, int repeats) {
  const bool thread_cpu = bench_uses_thread_cpu_time();
  for (std::size_t k = 0; k < tracers; ++k) trace(k);  // warm-up: page in the tree, settle the clocks
  std::vector<std::vector<double>> times(tracers);
  for (int r = 0; r < std::max(1, repeats); ++r)
    for (std::size_t k = 0; k < tracers; ++k) {
      const double t0 = clock_seconds(thread_cpu);
      trace(k);
      times[k].push_back(clock_seconds(thread_cpu) - t0);
    }
  std::vector<double> medians;
  for (const auto& t : times) medians.push_back(median(t));
  return medians;
}

void trace_closest(const RayTracer& t, const RaySet& set, std::vector<Hit>& hits) {
  const auto n = static_cast<int64_t>(set.rays.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t c = 0; c < n; c += int64_t(kChunk))
    t.closest(set.rays.data() + c, hits.data() + c, std::size_t(std::min<int64_t>(kChunk, n - c)));
}

void trace_occluded(const RayTracer& t, const RaySet& set, std::vector<uint8_t>& out) {
  const auto n = static_cast<int64_t>(set.rays.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t c = 0; c < n; c += int64_t(kChunk))
    t.occluded(set.rays.data() + c, out.data() + c, std::size_t(std::min<int64_t>(kChunk, n - c)));
}

void trace_tiles(const RayTracer& t, const BenchRays& b, std::vector<Hit>& hits) {
  const auto tiles = static_cast<int64_t>(b.tile_start.size()) - 1;
#pragma omp parallel for schedule(dynamic, kTileChunk)
  for (int64_t k = 0; k < tiles; ++k) {
    const uint32_t s = b.tile_start[k], e = b.tile_start[k + 1];
    t.closest_packet(b.tiles.rays.data() + s, hits.data() + s, e - s);
  }
}

void trace_shadow_tiles(const RayTracer& t, const BenchRays& b, std::vector<uint8_t>& out) {
  const auto tiles = static_cast<int64_t>(b.shadow_tile_start.size()) - 1;
#pragma omp parallel for schedule(dynamic, kTileChunk)
  for (int64_t k = 0; k < tiles; ++k) {
    const uint32_t s = b.shadow_tile_start[k], e = b.shadow_tile_start[k + 1];
    if (e > s) t.occluded_packet(b.shadow_tiles.rays.data() + s, out.data() + s, e - s);
  }
}

SetResult occluded_result(const RaySet& set, const std::vector<uint8_t>& occluded, double seconds) {
  SetResult r{set.rays.size(), 0, occluded_checksum(set, occluded), seconds};
  for (uint8_t o : occluded) r.hits += o;
  return r;
}

SetResult summarize(const RaySet& set, const std::vector<Hit>& hits, double seconds) {
  SetResult r{set.rays.size(), 0, hit_checksum(set, hits), seconds};
  for (const Hit& h : hits) r.hits += h.hit() ? 1 : 0;
  return r;
}

}  // namespace

bool bench_uses_thread_cpu_time() { return omp_get_max_threads() == 1; }

BenchRays make_bench_rays(const TriangleMesh& mesh, int width, int height, const RayTracer& reference) {
  BenchRays b;
  b.camera = frame_mesh(mesh, width, height);
  b.primary = primary_rays(b.camera);
  b.tiles = primary_tiles(b.camera, b.tile_start);
  std::vector<Hit> hits(b.primary.rays.size());
  trace_closest(reference, b.primary, hits);
  b.shadow = shadow_rays(b.camera, b.primary, hits);
  // the shadow rays again, by tiles: those of each tile's hits, in the tile's order
  // (the tiles hold the primary rays, pixel for pixel: their hits are the primary hits reordered)
  std::vector<Hit> tile_hits(b.tiles.rays.size());
  for (std::size_t j = 0; j < tile_hits.size(); ++j) tile_hits[j] = hits[b.tiles.pixel[j]];
  b.shadow_tiles = shadow_rays(b.camera, b.tiles, tile_hits);
  b.shadow_tile_start.assign(1, 0);
  for (std::size_t k = 0; k + 1 < b.tile_start.size(); ++k) {
    uint32_t n = b.shadow_tile_start.back();
    for (uint32_t i = b.tile_start[k]; i < b.tile_start[k + 1]; ++i) n += tile_hits[i].hit() ? 1u : 0u;
    b.shadow_tile_start.push_back(n);
  }
  b.incoherent = incoherent_rays(b.camera, mesh, b.primary, hits);
  return b;
}

std::vector<TracerRun> run_bench_rays(const std::vector<const RayTracer*>& tracers, const BenchRays& b,
                                      int repeats, const Progress& progress) {
  auto stage = [&](const char* set) {
    if (progress) progress(std::string("tracing ") + set);
  };
  const std::size_t n = tracers.size();
  std::vector<TracerRun> runs(n);
  for (TracerRun& run : runs) {
    run.primary_hits.resize(b.primary.rays.size());
    run.packet_hits.resize(b.tiles.rays.size());
    run.incoherent_hits.resize(b.incoherent.rays.size());
    run.shadow_occluded.resize(b.shadow.rays.size());
    run.shadow_packet_occluded.resize(b.shadow_tiles.rays.size());
  }
  stage("primary rays");
  auto s = median_seconds([&](std::size_t k) { trace_closest(*tracers[k], b.primary, runs[k].primary_hits); },
                          n, repeats);
  for (std::size_t k = 0; k < n; ++k) runs[k].primary = summarize(b.primary, runs[k].primary_hits, s[k]);
  stage("primary packets");
  s = median_seconds([&](std::size_t k) { trace_tiles(*tracers[k], b, runs[k].packet_hits); }, n, repeats);
  for (std::size_t k = 0; k < n; ++k) runs[k].primary_packet = summarize(b.tiles, runs[k].packet_hits, s[k]);
  stage("shadow rays");
  s = median_seconds([&](std::size_t k) { trace_occluded(*tracers[k], b.shadow, runs[k].shadow_occluded); },
                     n, repeats);
  for (std::size_t k = 0; k < n; ++k)
    runs[k].shadow = occluded_result(b.shadow, runs[k].shadow_occluded, s[k]);
  stage("shadow packets");
  s = median_seconds(
      [&](std::size_t k) { trace_shadow_tiles(*tracers[k], b, runs[k].shadow_packet_occluded); }, n, repeats);
  for (std::size_t k = 0; k < n; ++k)
    runs[k].shadow_packet = occluded_result(b.shadow_tiles, runs[k].shadow_packet_occluded, s[k]);
  stage("incoherent rays");
  s = median_seconds(
      [&](std::size_t k) { trace_closest(*tracers[k], b.incoherent, runs[k].incoherent_hits); }, n, repeats);
  for (std::size_t k = 0; k < n; ++k)
    runs[k].incoherent = summarize(b.incoherent, runs[k].incoherent_hits, s[k]);
  return runs;
}

Mismatches count_mismatches(const TracerRun& a, const TracerRun& b) {
  Mismatches m;
  auto ids = [](const std::vector<Hit>& x, const std::vector<Hit>& y) {
    uint64_t n = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) n += x[i].tri != y[i].tri;
    return n;
  };
  m.primary = ids(a.primary_hits, b.primary_hits);
  m.primary_packet = ids(a.packet_hits, b.packet_hits);
  m.incoherent = ids(a.incoherent_hits, b.incoherent_hits);
  for (std::size_t i = 0; i < a.shadow_occluded.size() && i < b.shadow_occluded.size(); ++i)
    m.shadow += a.shadow_occluded[i] != b.shadow_occluded[i];
  for (std::size_t i = 0; i < a.shadow_packet_occluded.size() && i < b.shadow_packet_occluded.size(); ++i)
    m.shadow_packet += a.shadow_packet_occluded[i] != b.shadow_packet_occluded[i];
  return m;
}

}  // namespace rayvec
