// RenderStats: how many rays of each kind a render traced and where the time went.
#pragma once
#include <cstdint>
#include <string>

namespace rayvec {

struct RayCounts {
  uint64_t primary = 0, shadow = 0, reflection = 0, refraction = 0;
  // Of the primary rays, those that hit the geometry (not a ray count of its own: not in total()).
  uint64_t primary_hits = 0;

  uint64_t total() const { return primary + shadow + reflection + refraction; }
  RayCounts& operator+=(const RayCounts& o) {
    primary += o.primary;
    primary_hits += o.primary_hits;
    shadow += o.shadow;
    reflection += o.reflection;
    refraction += o.refraction;
    return *this;
  }
};

struct RenderStats {
  RayCounts rays;
  // Wall-clock seconds per stage.
  double load_seconds = 0, build_seconds = 0, render_seconds = 0, write_seconds = 0;
  // Thread-seconds inside the render, summed over threads: primary-ray tracing (closest_stream)
  // and everything after it (shading, shadow/reflection/refraction rays).
  double primary_thread_seconds = 0, shading_thread_seconds = 0;
  int threads = 1;

  double rays_per_second() const { return render_seconds > 0 ? double(rays.total()) / render_seconds : 0.0; }
  // Human-readable lines for --stats.
  std::string text() const;
  // {"rays": {"primary": n, "shadow": n, "reflection": n, "refraction": n, "total": n,
  //           "primary_hits": n},
  //  "seconds": {"load": s, "build": s, "render": s, "write": s, "total": s, ...}, ...}
  std::string json() const;
};

}  // namespace rayvec
