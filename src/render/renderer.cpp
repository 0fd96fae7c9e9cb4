#include "render/renderer.h"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

#include "platform/stopwatch.h"
#include "render/camera_rays.h"
#include "render/pixel_cost.h"
#include "render/render_budget.h"

namespace rayvec {
namespace {

constexpr int kTile = 16;

// A 32-bit integer hash (Wellons' "lowbias32"): decorrelated jitter without a stateful RNG, so the
// image does not depend on which thread renders which tile.
uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

float unit_float(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

std::vector<std::string> channel_names(const RenderSettings::Aovs& aov) {
  std::vector<std::string> names{"R", "G", "B"};
  if (aov.depth) names.push_back("Z");
  if (aov.normal) names.insert(names.end(), {"N.x", "N.y", "N.z"});
  if (aov.id) names.insert(names.end(), {"id", "object_id"});
  if (aov.cost) names.insert(names.end(), {"cost.nodes", "cost.triangles"});
  if (aov.bounces) names.push_back("bounces");
  return names;
}

}  // namespace

std::pair<float, float> sample_position(int x, int y, int s, int n) {
  if (n <= 1) return {0.5f, 0.5f};
  const uint32_t seed = hash32(uint32_t(x) * 0x9e3779b9U ^ hash32(uint32_t(y) + 0x632be5abU));
  const float jx = unit_float(hash32(seed ^ uint32_t(2 * s))),
              jy = unit_float(hash32(seed ^ uint32_t(2 * s + 1)));
  const int k = static_cast<int>(std::lround(std::sqrt(double(n))));
  if (k * k == n) return {(float(s % k) + jx) / float(k), (float(s / k) + jy) / float(k)};
  // N-rooks: sample s takes column stratum s and a row stratum from a per-pixel rotation.
  const int row = int((uint32_t(s) + seed) % uint32_t(n));
  return {(float(s) + jx) / float(n), (float(row) + jy) / float(n)};
}

Image render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings, RenderStats& stats,
             const std::function<void(double)>& progress) {
  const Camera& cam = scene.camera;
  // Before any allocation: an absurd size or a framebuffer beyond free memory fails now, exit 2.
  check_render_budget(scene, static_cast<int>(channel_names(settings.aov).size()), available_memory_bytes());
  const CameraRays camera(cam);
  const bool counting = settings.aov.cost || settings.aov.bounces;
  Image image(cam.width, cam.height, channel_names(settings.aov));
  const int nc = image.nchannels();
  const int tiles_x = (cam.width + kTile - 1) / kTile, tiles_y = (cam.height + kTile - 1) / kTile;
  const int tiles = tiles_x * tiles_y, spp = std::max(1, settings.spp);
  std::atomic<int> done{0};
  RayCounts total;
  double primary_seconds = 0, shading_seconds = 0;
  const auto t0 = std::chrono::steady_clock::now();

  // No more threads than tiles: a one-tile image would otherwise pay for starting and joining
  // threads that have nothing to do (a 16x16 render: 3.5x the CPU time of the whole process).
#pragma omp parallel num_threads(std::max(1, std::min(omp_get_max_threads(), tiles)))
  {
    RayCounts rays;
    double primary_s = 0, shading_s = 0;
    std::vector<Ray> batch;
    std::vector<Hit> hits;
    std::vector<Vec3f> sum;
    std::vector<TraversalCost> costs;
    std::vector<int> bounces;
    PixelCost pixel_cost(accel);
    const Whitted whitted(scene, accel, settings, counting ? &pixel_cost : nullptr);
#pragma omp for schedule(dynamic, 1)
    for (int tile = 0; tile < tiles; ++tile) {
      const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
      const int x1 = std::min(x0 + kTile, cam.width), y1 = std::min(y0 + kTile, cam.height);
      const int w = x1 - x0, n = w * (y1 - y0);
      sum.assign(n, Vec3f{});
      if (counting) {
        costs.assign(n, TraversalCost{});
        bounces.assign(n, 0);
      }
      for (int s = 0; s < spp; ++s) {
        const auto ta = std::chrono::steady_clock::now();
        batch.resize(n);
        hits.resize(n);
        for (int i = 0; i < n; ++i) {
          const int x = x0 + i % w, y = y0 + i / w;
          const auto [sx, sy] = sample_position(x, y, s, spp);
          batch[i] = camera.ray(float(x) + sx, float(y) + sy);
        }
        accel.closest_stream(batch.data(), hits.data(), n);
        rays.primary += uint64_t(n);
        const auto tb = std::chrono::steady_clock::now();
        primary_s += std::chrono::duration<double>(tb - ta).count();
        for (int i = 0; i < n; ++i) {
          if (counting) pixel_cost.reset();
          sum[i] += whitted.shade(batch[i], hits[i], 0, 1.0f, rays);
          if (counting) {
            costs[i] += pixel_cost.cost;
            bounces[i] = std::max(bounces[i], pixel_cost.bounces);
          }
          if (s != 0 || nc == 3) continue;
          // AOVs from the first sample.
          float* px = &image.at(x0 + i % w, y0 + i / w, 3);
          const Hit& h = hits[i];
          SurfacePoint sp;
          if (h.hit()) sp = surface_point(scene, batch[i], h);
          if (settings.aov.depth) *px++ = h.hit() ? h.t * dot(batch[i].dir, camera.forward()) : kInf;
          if (settings.aov.normal) {
            const Vec3f nrm = h.hit() ? sp.ns : Vec3f{};
            *px++ = nrm.x;
            *px++ = nrm.y;
            *px++ = nrm.z;
          }
          if (settings.aov.id) {
            *px++ = float(h.tri);
            *px++ = h.hit() ? float(scene.triangle_object[h.tri]) : -1.0f;
          }
        }
        shading_s += seconds_since(tb);
      }
      for (int i = 0; i < n; ++i) {
        const Vec3f c = sum[i] * (1.0f / float(spp));
        float* px = &image.at(x0 + i % w, y0 + i / w, 0);
        px[0] = c.x;
        px[1] = c.y;
        px[2] = c.z;
        if (!counting) continue;
        px += image.nchannels() - (settings.aov.cost ? 2 : 0) - (settings.aov.bounces ? 1 : 0);
        if (settings.aov.cost) {
          *px++ = float(costs[i].nodes);
          *px++ = float(costs[i].triangles);
        }
        if (settings.aov.bounces) *px = float(bounces[i]);
      }
      const int finished = ++done;
      if (progress && omp_get_thread_num() == 0) progress(double(finished) / tiles);
    }
#pragma omp critical(rayvec_render_stats)
    {
      total += rays;
      primary_seconds += primary_s;
      shading_seconds += shading_s;
    }
  }
  stats.render_seconds = seconds_since(t0);
  stats.rays = total;
  stats.primary_thread_seconds = primary_seconds;
  stats.shading_thread_seconds = shading_seconds;
  stats.threads = omp_get_max_threads();
  if (progress) progress(1.0);
  return image;
}

}  // namespace rayvec
