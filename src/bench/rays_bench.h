// The measurements of `rayvec bench rays`: the three ray sets of ray_sets.h traced by a RayTracer
// (primary and shadow rays also as packets of 4×4 tiles),
// each timed as the median of `repeats` runs after one warm-up run (tracing and storing results
// timed, ray generation not), OpenMP-parallel over chunks of rays or 4×4 tiles. With one thread the
// clock is the thread's CPU time (stable on a shared machine), otherwise the wall clock. Printing lives in
// src/app/cmd_bench_rays.cpp.
#pragma once
#include <cstdint>
#include <vector>

#include "bench/ray_sets.h"
#include "bench/ray_tracer.h"
#include "io/progress.h"

namespace rayvec {

// True when ray sets are timed on the thread's CPU-time clock (omp_get_max_threads() == 1).
bool bench_uses_thread_cpu_time();

struct SetResult {
  uint64_t rays = 0, hits = 0, checksum = 0;
  double seconds = 0;
  double mrays_per_s() const { return seconds > 0 ? double(rays) / seconds * 1e-6 : 0.0; }
};

// The rays every tracer traces. Shadow and incoherent rays start at the primary hits of the
// reference tracer (rayvec), so a rival traces exactly the same rays.
struct BenchRays {
  BenchCamera camera;
  RaySet primary;                    // row-major pixels
  RaySet tiles;                      // the same rays by 4×4 tiles
  std::vector<uint32_t> tile_start;  // tiles.rays[tile_start[k] .. tile_start[k+1])
  RaySet shadow, incoherent;
  RaySet shadow_tiles;                      // the shadow rays by 4×4 tiles (of the tiles' hits)
  std::vector<uint32_t> shadow_tile_start;  // shadow_tiles.rays[shadow_tile_start[k] .. [k+1])
};
BenchRays make_bench_rays(const TriangleMesh& mesh, int width, int height, const RayTracer& reference);

struct TracerRun {
  SetResult primary, primary_packet, shadow, shadow_packet, incoherent;
  std::vector<Hit> primary_hits, packet_hits, incoherent_hits;   // packet_hits in tile order
  std::vector<uint8_t> shadow_occluded, shadow_packet_occluded;  // the latter in tile order
};
// Traces every set with every tracer. The runs are interleaved — for each set, one warm-up per
// tracer, then repeat r of tracer 0, repeat r of tracer 1, … — so that the tracers share the same
// stretches of machine time: on a VM whose speed drifts for seconds at a time, timing one tracer's
// five runs and then the other's would put the drift into the ratio. One TracerRun per tracer.
// `progress`, if set, is told each set before it runs.
std::vector<TracerRun> run_bench_rays(const std::vector<const RayTracer*>& tracers, const BenchRays& rays,
                                      int repeats, const Progress& progress = {});

// Rays whose triangle id (or occlusion) differs between two runs, per set.
struct Mismatches {
  uint64_t primary = 0, primary_packet = 0, shadow = 0, shadow_packet = 0, incoherent = 0;
};
Mismatches count_mismatches(const TracerRun& a, const TracerRun& b);

}  // namespace rayvec
