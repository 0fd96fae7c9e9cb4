#include "render/tile_renderer.h"

#include <algorithm>
#include <chrono>

#include "platform/stopwatch.h"
#include "render/renderer.h"
#include "render/surface_point.h"

namespace rayvec {

std::vector<std::string> render_channel_names(const RenderSettings::Aovs& aov) {
  std::vector<std::string> names{"R", "G", "B"};
  if (aov.depth) names.push_back("Z");
  if (aov.normal) names.insert(names.end(), {"N.x", "N.y", "N.z"});
  if (aov.id) names.insert(names.end(), {"id", "object_id"});
  if (aov.cost) names.insert(names.end(), {"cost.nodes", "cost.triangles"});
  if (aov.bounces) names.push_back("bounces");
  return names;
}

TileRenderer::TileRenderer(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                           const CameraRays& camera, const TriangleNormals* normals)
    : scene_(scene),
      accel_(accel),
      settings_(settings),
      camera_(camera),
      normals_(normals),
      channels_(static_cast<int>(render_channel_names(settings.aov).size())),
      counting_(settings.aov.cost || settings.aov.bounces),
      pixel_cost_(accel),
      whitted_(scene, accel, settings, counting_ ? &pixel_cost_ : nullptr, normals),
      samples_(settings.spp),
      lighting_(scene, accel, whitted_),
      waves_(scene, accel, whitted_) {}

void TileRenderer::render(const TileRect& rect, float* out) {
  const int w = rect.width(), n = rect.pixels(), spp = samples_.count();
  sum_.assign(n, Vec3f{});
  if (counting_) {
    costs_.assign(n, TraversalCost{});
    bounces_.assign(n, 0);
  }
  // rays go by 4×4 blocks (a packet's rays closer together than a row's); pixel = block_order_[ray]
  block_order_.clear();
  seeds_.clear();
  pixel_x_.clear();
  pixel_y_.clear();
  const int h = n / w;
  for (int by = 0; by < h; by += 4)
    for (int bx = 0; bx < w; bx += 4)
      for (int y = by; y < std::min(by + 4, h); ++y)
        for (int x = bx; x < std::min(bx + 4, w); ++x) {
          block_order_.push_back(y * w + x);
          const int px = rect.x0 + x, py = rect.y0 + y;
          seeds_.push_back(spp > 1 ? PixelSamples::seed(px, py) : 0);  // one sample: the centre, no jitter
          pixel_x_.push_back(float(px));
          pixel_y_.push_back(float(py));
        }
  sample_x_.resize(n);
  sample_y_.resize(n);
  for (int s = 0; s < spp; ++s) {
    const auto ta = std::chrono::steady_clock::now();
    batch_.resize(n);
    hits_.resize(n);
    for (int j = 0; j < n; ++j) {
      const auto [sx, sy] = samples_.position(seeds_[j], s);
      sample_x_[j] = pixel_x_[j] + sx;
      sample_y_[j] = pixel_y_[j] + sy;
    }
    camera_.rays(sample_x_.data(), sample_y_.data(), n, batch_.data());
    accel_.closest_stream(batch_.data(), hits_.data(), n);
    rays.primary += uint64_t(n);
    const auto tb = std::chrono::steady_clock::now();
    primary_seconds += std::chrono::duration<double>(tb - ta).count();
    const bool together = !counting_;
    if (together) {
      lighting_.light(batch_.data(), hits_.data(), n);
      rays.shadow += lighting_.shadow_rays();
      radiance_.resize(std::size_t(n));
      waves_.shade(batch_.data(), hits_.data(), n, lighting_, radiance_.data(), rays);
    }
    for (int j = 0; j < n; ++j) {
      const int i = block_order_[j];
      const Ray& ray = batch_[j];
      const Hit& h = hits_[j];
      const bool lit = together && lighting_.lit(j);
      rays.primary_hits += h.hit() ? 1 : 0;
      if (counting_) pixel_cost_.reset();
      if (lit && lighting_.finished(j))
        sum_[i] += lighting_.radiance(j);
      else if (lit)
        sum_[i] += radiance_[std::size_t(j)];
      else
        sum_[i] += whitted_.shade(ray, h, 0, 1.0f, rays);
      if (counting_) {
        costs_[i] += pixel_cost_.cost;
        bounces_[i] = std::max(bounces_[i], pixel_cost_.bounces);
      }
      if (s != 0 || channels_ == 3) continue;
      // AOVs from the first sample.
      float* px = out + std::size_t(i) * channels_ + 3;
      SurfacePoint sp;
      if (h.hit()) sp = lit ? lighting_.surface(j) : surface_point(scene_, ray, h, normals_);
      if (settings_.aov.depth) *px++ = h.hit() ? h.t * dot(ray.dir, camera_.forward()) : kInf;
      if (settings_.aov.normal) {
        const Vec3f nrm = h.hit() ? sp.ns : Vec3f{};
        *px++ = nrm.x;
        *px++ = nrm.y;
        *px++ = nrm.z;
      }
      if (settings_.aov.id) {
        *px++ = float(h.tri);
        *px++ = h.hit() ? float(scene_.triangle_object[h.tri]) : -1.0f;
      }
    }
    shading_seconds += seconds_since(tb);
  }
  for (int i = 0; i < n; ++i) {
    const Vec3f c = sum_[i] * (1.0f / float(spp));
    float* px = out + std::size_t(i) * channels_;
    px[0] = c.x;
    px[1] = c.y;
    px[2] = c.z;
    if (!counting_) continue;
    px += channels_ - (settings_.aov.cost ? 2 : 0) - (settings_.aov.bounces ? 1 : 0);
    if (settings_.aov.cost) {
      *px++ = float(costs_[i].nodes);
      *px++ = float(costs_[i].triangles);
    }
    if (settings_.aov.bounces) *px = float(bounces_[i]);
  }
}

}  // namespace rayvec
