#include "image/srgb8.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "image/image_io.h"
#include "platform/attributes.h"

namespace rayvec {
namespace {

// thresholds[k - 1]: the smallest non-negative float whose reference byte is k or more.
std::array<float, 255> make_thresholds() {
  std::array<float, 255> thresholds{};
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  for (int k = 1; k <= 255; ++k) {
    std::uint32_t lo = 0, hi = one;  // reference(1.0f) = 255 >= k: the answer is in [lo, hi]
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (srgb8_reference(std::bit_cast<float>(mid)) >= k)
        hi = mid;
      else
        lo = mid + 1;
    }
    thresholds[k - 1] = std::bit_cast<float>(lo);
  }
  return thresholds;
}

// Below 2^-13 every value is byte 0 (byte 1 starts near 1.5e-4). From there to 1, the top 16 bits
// of a float (exponent and 7 mantissa bits) name a bucket narrower than a byte step wherever the
// steps are dense, so the bucket's first byte is off by at most one step (the table's maker counts
// them): kSteps compares that add 0 or 1 finish the lookup without a branch to mispredict — a loop
// that stops at the right threshold mispredicts about once a pixel channel.
constexpr float kSmallest = 1.0f / 8192.0f;
constexpr int kSteps = 2;
constexpr std::uint32_t kFirstBucket = std::bit_cast<std::uint32_t>(kSmallest) >> 16;
constexpr std::uint32_t kBuckets = (std::bit_cast<std::uint32_t>(1.0f) >> 16) - kFirstBucket;

struct Tables {
  // thresholds[255] = +inf: a step from byte 255 adds 0
  std::array<float, 256> thresholds{};
  std::array<std::uint8_t, kBuckets> first{};  // the byte of each bucket's smallest float
  bool few_steps = true;                       // no bucket spans more than kSteps thresholds

  Tables() {
    const std::array<float, 255> t = make_thresholds();
    std::copy(t.begin(), t.end(), thresholds.begin());
    thresholds[255] = INFINITY;
    for (std::uint32_t b = 0; b < kBuckets; ++b) {
      const float low = std::bit_cast<float>((kFirstBucket + b) << 16);
      const float next = std::bit_cast<float>((kFirstBucket + b + 1) << 16);
      const auto k0 = std::upper_bound(t.begin(), t.end(), low),
                 k1 = std::lower_bound(t.begin(), t.end(), next);
      first[b] = static_cast<std::uint8_t>(k0 - t.begin());
      few_steps = few_steps && k1 - k0 <= kSteps;
    }
  }
};

}  // namespace

const float* srgb8_decode_table() {
  static const std::array<float, 256> linear = [] {
    std::array<float, 256> table{};
    for (int k = 0; k < 256; ++k) table[std::size_t(k)] = srgb_decode(float(k) * (1.0f / 255.0f));
    return table;
  }();
  return linear.data();
}

std::uint8_t srgb8_reference(float linear) {
  const float e = std::isnan(linear) ? 0.0f : std::clamp(srgb_encode(linear), 0.0f, 1.0f);
  return static_cast<std::uint8_t>(std::lround(e * 255.0f));
}

namespace {

const Tables& tables() {
  static const Tables t;
  return t;
}

// The lookup without a data-dependent branch: NaN, negative, zero and tiny values become
// kSmallest (byte 0) and values from 1 up the float just below 1 (byte 255) by two selects, so
// dark and saturated pixels cost what mid-tones cost.
RAYVEC_INLINE unsigned lookup(const Tables& t, float linear) {
  constexpr float kBelowOne = 0x1.fffffep-1f;
  float x = linear >= kSmallest ? linear : kSmallest;
  x = x < kBelowOne ? x : kBelowOne;
  unsigned k = t.first[(std::bit_cast<std::uint32_t>(x) >> 16) - kFirstBucket];
  for (int s = 0; s < kSteps; ++s) k += x >= t.thresholds[k] ? 1u : 0u;
  return k;
}

unsigned lookup_slow(const Tables& t, float linear) {
  if (!(linear >= kSmallest)) return 0;
  if (linear >= 1.0f) return 255;
  unsigned k = t.first[(std::bit_cast<std::uint32_t>(linear) >> 16) - kFirstBucket];
  while (linear >= t.thresholds[k]) ++k;
  return k;
}

}  // namespace

std::uint8_t srgb8(float linear) {
  const Tables& t = tables();
  return static_cast<std::uint8_t>(t.few_steps ? lookup(t, linear) : lookup_slow(t, linear));
}

void srgb8_pixels(const float* linear, int channels, std::size_t count, std::uint8_t* rgb) {
  const Tables& t = tables();
  if (!t.few_steps) [[unlikely]] {
    for (std::size_t p = 0; p < count; ++p)
      for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = srgb8(c < channels ? linear[p * channels + c] : 0.0f);
    return;
  }
  if (channels >= 3) {
    for (std::size_t p = 0; p < count; ++p, linear += channels, rgb += 3) {
      rgb[0] = static_cast<std::uint8_t>(lookup(t, linear[0]));
      rgb[1] = static_cast<std::uint8_t>(lookup(t, linear[1]));
      rgb[2] = static_cast<std::uint8_t>(lookup(t, linear[2]));
    }
    return;
  }
  for (std::size_t p = 0; p < count; ++p)
    for (int c = 0; c < 3; ++c)
      rgb[p * 3 + c] = static_cast<std::uint8_t>(lookup(t, c < channels ? linear[p * channels + c] : 0.0f));
}

}  // namespace rayvec
