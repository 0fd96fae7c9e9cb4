// PixelSamples: where the samples of a pixel lie. The centre for one sample a pixel, a jittered k×k
// grid for n = k², otherwise jittered N-rooks (one sample per row and per column stratum). The
// jitter is hashed from the pixel and the sample's index, never drawn from a stateful generator, so
// a pixel's samples do not depend on which thread, rank or order renders it.
#pragma once
#include <cstdint>
#include <utility>

namespace rayvec {

class PixelSamples {
 public:
  explicit PixelSamples(int n);  // n samples a pixel; n ≤ 1 means one

  // The hash of pixel (x, y) that its samples' jitter starts from.
  static uint32_t seed(int x, int y);

  // The position in [0,1)² of sample s (0 ≤ s < count()) of the pixel with this seed. Inline: the
  // camera's loop over a tile's pixels overlaps the divisions of neighbouring pixels.
  std::pair<float, float> position(uint32_t pixel_seed, int s) const {
    if (n_ == 1) return {0.5f, 0.5f};
    const float jx = unit_float(hash32(pixel_seed ^ uint32_t(2 * s))),
                jy = unit_float(hash32(pixel_seed ^ uint32_t(2 * s + 1)));
    if (grid_ != 0) {
      const float k = float(grid_);
      return {(float(s % grid_) + jx) / k, (float(s / grid_) + jy) / k};
    }
    // N-rooks: sample s takes column stratum s and a row stratum from a per-pixel rotation.
    const int row = int((uint32_t(s) + pixel_seed) % uint32_t(n_));
    return {(float(s) + jx) / float(n_), (float(row) + jy) / float(n_)};
  }

  int count() const { return n_; }

 private:
  // A 32-bit integer hash (Wellons' "lowbias32"): decorrelated jitter without a stateful RNG.
  static uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
  }
  static float unit_float(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

  int n_;
  int grid_;  // k when n = k² (a k×k grid), else 0 (N-rooks)
};

// Sample s of n in pixel (x, y): PixelSamples(n).position(PixelSamples::seed(x, y), s).
std::pair<float, float> sample_position(int x, int y, int s, int n);

}  // namespace rayvec
