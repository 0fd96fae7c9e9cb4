// render(): the pipeline from camera to framebuffer. The image is cut into 16×16 tiles rendered in
// parallel (OpenMP, dynamic schedule: tiles with glass cost far more than background); in each tile
// the primary rays of one sample go to Accelerator::closest_stream together (a coherent packet),
// then every hit is shaded by the Whitted integrator, which traces its secondary rays one by one.
#pragma once
#include <functional>

#include "accel/accelerator.h"
#include "image/image.h"
#include "render/render_stats.h"
#include "render/whitted.h"
#include "scene/scene.h"

namespace rayvec {

struct RenderOptions {
  int spp = 1;  // samples per pixel: 1 = the pixel centre; more = stratified (see sample_position)
  WhittedSettings whitted;
  // Extra EXR channels, from each pixel's first sample: Z (camera-space depth along the view axis,
  // +inf for background), N.x N.y N.z (world shading normal facing the camera, 0 for background),
  // id (triangle id) and object_id (-1 for background).
  bool aov_depth = false, aov_normal = false, aov_id = false;
  // Called from one thread now and then with the finished fraction (0..1]; may be empty.
  std::function<void(double)> progress;
};

// Renders the scene; fills stats.rays, stats.render_seconds and the thread-time fields.
// The result is independent of the number of threads.
Image render(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
             RenderStats& stats);

// The position in [0,1)² of sample `s` of `n` inside pixel (x, y): the centre for n = 1, a jittered
// k×k grid when n = k², otherwise jittered N-rooks (one sample per row and per column stratum).
// Deterministic: hashed from (x, y, s).
std::pair<float, float> sample_position(int x, int y, int s, int n);

}  // namespace rayvec
