#include "render/pixel_samples.h"

#include <algorithm>
#include <cmath>

namespace rayvec {

PixelSamples::PixelSamples(int n) : n_(std::max(1, n)), grid_(0) {
  const int k = static_cast<int>(std::lround(std::sqrt(double(n_))));
  if (k * k == n_) grid_ = k;
}

uint32_t PixelSamples::seed(int x, int y) {
  return hash32(uint32_t(x) * 0x9e3779b9U ^ hash32(uint32_t(y) + 0x632be5abU));
}

std::pair<float, float> sample_position(int x, int y, int s, int n) {
  return PixelSamples(n).position(PixelSamples::seed(x, y), s);
}

}  // namespace rayvec
