// check_render_budget: absurd image sizes and framebuffers beyond free memory are refused before
// any work, with a message that gives the numbers and what to change.
#include <gtest/gtest.h>

#include "io/input_error.h"
#include "render/render_budget.h"

namespace rayvec {
namespace {

std::string message_of(const Scene& scene, int channels, std::size_t available) {
  try {
    check_render_budget(scene, channels, available);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RenderBudget, RefusesSizesOutsideTheLimits) {
  Scene scene;
  scene.source = "s.json";
  for (auto [w, h] : {std::pair{0, 10}, {10, -1}, {1000000, 1000000}, {16385, 1}}) {
    scene.camera.width = w;
    scene.camera.height = h;
    const std::string m = message_of(scene, 3, 0);
    EXPECT_NE(m.find("s.json: image size " + std::to_string(w) + "x" + std::to_string(h) +
                     " is outside 1..16384 pixels a side"),
              std::string::npos)
        << m;
  }
  scene.camera.width = scene.camera.height = 16384;
  EXPECT_EQ(message_of(scene, 3, 0), "");  // 0 = memory unknown: only the size is checked
}

TEST(RenderBudget, RefusesAFramebufferBeyondAvailableMemory) {
  Scene scene;
  scene.source = "s.json";
  scene.camera.width = 1000;
  scene.camera.height = 500;
  const std::size_t need = render_peak_bytes(1000, 500, 9);
  EXPECT_EQ(need, 2u * 1000 * 500 * 9 * 4);
  EXPECT_EQ(message_of(scene, 9, need), "");
  const std::string m = message_of(scene, 9, need - 1);
  EXPECT_NE(m.find("s.json: a 1000x500 image with 9 channels needs 0.04 GB of memory, but only "
                   "0.04 GB is available; lower --width/--height or drop --aov channels"),
            std::string::npos)
      << m;
}

TEST(RenderBudget, ReadsAvailableMemory) {
  EXPECT_GT(available_memory_bytes(), 0u);  // Linux: /proc/meminfo
}

}  // namespace
}  // namespace rayvec
