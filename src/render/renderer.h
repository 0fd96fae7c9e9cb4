// render(): the pipeline from camera to framebuffer. The image is cut into 16×16 tiles rendered in
// parallel (OpenMP, dynamic schedule: tiles with glass cost far more than background); in each tile
// the primary rays of one sample go to Accelerator::closest_stream together (a coherent packet),
// then the shadow rays of their hits, light by light, to Accelerator::occluded_stream together, and
// every hit is shaded by the Whitted integrator, which traces the deeper rays one by one.
#pragma once
#include <functional>

#include "accel/accelerator.h"
#include "image/image.h"
#include "render/render_stats.h"
#include "render/whitted.h"
#include "scene/scene.h"

namespace rayvec {

// Renders the scene under `settings` (usually scene.render; samples placed by PixelSamples, the AOVs as
// extra channels after R, G, B); fills stats.rays, stats.render_seconds and the thread-time fields.
// The result is independent of the number of threads. `progress`, if set, is called from one thread
// now and then with the finished fraction (0..1].
Image render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings, RenderStats& stats,
             const std::function<void(double)>& progress = {});

}  // namespace rayvec
