// Resource checks a render makes before any work, so that an absurd request fails at once with a
// message saying the limit and what to change, instead of thrashing or being killed midway.
#pragma once
#include <cstddef>

#include "scene/scene.h"

namespace rayvec {

// Bytes a render of `width`×`height` with `channels` float channels holds at its peak: the float
// framebuffer plus the encoded copy image_io.cpp builds in memory before the atomic write.
std::size_t render_peak_bytes(int width, int height, int channels);

// Memory this process may still take: MemAvailable of /proc/meminfo (0 when unknown).
std::size_t available_memory_bytes();

// Throws InputError (exit 2) naming the scene when the camera's size is not 1..16384 a side or
// the render would need more memory than `available` bytes (0 = do not check memory); the message
// gives the need, the limit, and how to lower the need (--width/--height, fewer --aov channels).
void check_render_budget(const Scene& scene, int channels, std::size_t available);

}  // namespace rayvec
