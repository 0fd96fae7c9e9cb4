#include "render/render_stats.h"

#include <cstdio>

namespace rayvec {
namespace {

// printf into a string of whatever length the result needs (the JSON is longer than any fixed
// buffer worth keeping on the stack: a 256-byte one used to cut it off mid-object).
std::string format(const char* fmt, auto... args) {
  const int n = std::snprintf(nullptr, 0, fmt, args...);
  if (n <= 0) return {};
  std::string out(std::size_t(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), fmt, args...);
  out.resize(std::size_t(n));
  return out;
}

}  // namespace

std::string RenderStats::text() const {
  std::string s;
  s += format("rays: %llu primary, %llu shadow, %llu reflection, %llu refraction (%llu total)\n",
              (unsigned long long)rays.primary, (unsigned long long)rays.shadow,
              (unsigned long long)rays.reflection, (unsigned long long)rays.refraction,
              (unsigned long long)rays.total());
  s += format("camera rays that hit: %llu of %llu (%.1f %%)\n", (unsigned long long)rays.primary_hits,
              (unsigned long long)rays.primary,
              rays.primary ? 100.0 * double(rays.primary_hits) / double(rays.primary) : 0.0);
  s += format("rays/s: %.4g (%d threads)\n", rays_per_second(), threads);
  s += format("time: load %.3f s, build %.3f s, render %.3f s, write %.3f s\n", load_seconds, build_seconds,
              render_seconds, write_seconds);
  s += format("render thread-time: primary rays %.3f s, shading + secondary rays %.3f s\n",
              primary_thread_seconds, shading_thread_seconds);
  return s;
}

std::string RenderStats::json() const {
  return format(
      "{\n  \"rays\": {\"primary\": %llu, \"shadow\": %llu, \"reflection\": %llu, "
      "\"refraction\": %llu, \"total\": %llu, \"primary_hits\": %llu},\n"
      "  \"seconds\": {\"load\": %.6f, \"build\": %.6f, \"render\": %.6f, \"write\": %.6f, "
      "\"total\": %.6f, \"primary_thread\": %.6f, \"shading_thread\": %.6f},\n"
      "  \"rays_per_second\": %.6g,\n  \"threads\": %d\n}\n",
      (unsigned long long)rays.primary, (unsigned long long)rays.shadow, (unsigned long long)rays.reflection,
      (unsigned long long)rays.refraction, (unsigned long long)rays.total(),
      (unsigned long long)rays.primary_hits, load_seconds, build_seconds, render_seconds, write_seconds,
      load_seconds + build_seconds + render_seconds + write_seconds, primary_thread_seconds,
      shading_thread_seconds, rays_per_second(), threads);
}

}  // namespace rayvec
