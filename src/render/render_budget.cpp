#include "render/render_budget.h"

#include <cstdio>
#include <fstream>
#include <string>

#include "io/input_error.h"

namespace rayvec {
namespace {

constexpr int kMaxSide = 16384;  // the same bound the scene loader and --width/--height apply

std::string gigabytes(std::size_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f GB", double(bytes) / 1e9);
  return buf;
}

}  // namespace

std::size_t render_peak_bytes(int width, int height, int channels) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  // Framebuffer (float per channel) + encoded file image of at most the same size (EXR float or
  // PNG 8-bit, which is smaller).
  return 2 * pixels * std::size_t(channels) * sizeof(float);
}

std::size_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::size_t kb = 0;
  while (in >> key >> kb) {
    if (key == "MemAvailable:") return kb * 1024;
    in.ignore(256, '\n');
  }
  return 0;
}

void check_render_budget(const Scene& scene, int channels, std::size_t available) {
  const Camera& c = scene.camera;
  if (c.width < 1 || c.width > kMaxSide || c.height < 1 || c.height > kMaxSide)
    throw InputError(scene.source, 0,
                     "image size " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                         " is outside 1..16384 pixels a side");
  const std::size_t need = render_peak_bytes(c.width, c.height, channels);
  if (available > 0 && need > available)
    throw InputError(scene.source, 0,
                     "a " + std::to_string(c.width) + "x" + std::to_string(c.height) + " image with " +
                         std::to_string(channels) + " channels needs " + gigabytes(need) +
                         " of memory, but only " + gigabytes(available) +
                         " is available; lower --width/--height or drop --aov channels");
}

}  // namespace rayvec
