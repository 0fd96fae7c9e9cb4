// The binned builder's shortcuts give its plain arithmetic's answers: the partition's one comparison
// against right_threshold sends every centroid where bin_of sends it (NaN, infinities, signed zeros,
// denormals and the floats next to every bin boundary included), and the sweeps' 4-lane area is
// BBox::half_area bit for bit; Float4::with_lane, which the spatial-split search's clipped boxes use.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "bvh/sah_bins.h"

namespace rayvec {
namespace {

using namespace sah_bins;

constexpr float kFloatInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Centroids worth asking about for one binning: the special values, the range's ends, and the floats
// around each bin's lower edge (where bin_of changes) and around the threshold itself.
std::vector<float> probes(float lo, float scale, int bins, float threshold, std::mt19937& rng) {
  std::vector<float> c = {kNaN,    -kNaN,  kFloatInf, -kFloatInf, 0.0f, -0.0f,    1e-45f,
                          -1e-45f, 1e-38f, -3e38f,    3e38f,      lo,   threshold};
  for (int k = 0; k <= bins; ++k) c.push_back(lo + float(k) / scale);
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i) {  // up to three floats either side
    float up = c[i], down = c[i];
    for (int d = 0; d < 3 && std::isfinite(c[i]); ++d) {
      up = std::nextafter(up, kFloatInf);
      down = std::nextafter(down, -kFloatInf);
      c.push_back(up);
      c.push_back(down);
    }
  }
  std::uniform_real_distribution<float> u(-1.0f, 2.0f);
  for (int i = 0; i < 200; ++i) c.push_back(lo + u(rng) * float(bins) / scale);
  return c;
}

TEST(SahBins, OneComparisonWithTheThresholdSendsEveryCentroidToItsBinsSide) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> log_extent(-30.0f, 30.0f), offset(-1e3f, 1e3f);
  for (int trial = 0; trial < 300; ++trial) {
    const int bins = trial % 3 == 0 ? 32 : 2 + int(rng() % 63);
    float lo = offset(rng), extent = std::exp2(log_extent(rng));
    if (trial == 1) lo = 0.0f, extent = 1e-44f;  // a denormal extent: scale is infinite
    if (trial == 2) lo = -0.0f, extent = 1.0f;
    const float scale = float(bins) / extent;
    for (int last_left = 0; last_left < bins; ++last_left) {
      const float t = right_threshold(lo, scale, bins, last_left);
      for (float c : probes(lo, scale, bins, t, rng)) {
        const bool left = bin_of(c, lo, scale, bins) <= last_left;
        ASSERT_EQ(!(c >= t), left) << "c " << c << " lo " << lo << " scale " << scale << " bins " << bins
                                   << " last_left " << last_left << " threshold " << t;
      }
    }
  }
}

TEST(SahBins, ThresholdIsNaNWhenEveryBinGoesLeft) {
  EXPECT_TRUE(std::isnan(right_threshold(0.0f, 8.0f, 8, 7)));  // the last bin is left's
  EXPECT_TRUE(std::isnan(right_threshold(0.0f, 0.0f, 8, 0)));  // scale 0: every centroid in bin 0
}

TEST(SahBins, FloatRankOrdersEveryFloat) {
  const float in_order[] = {-kFloatInf, -3e38f, -1.0f, -1e-45f, -0.0f, 0.0f, 1e-45f, 1.0f, 3e38f, kFloatInf};
  for (std::size_t i = 0; i + 1 < std::size(in_order); ++i)
    EXPECT_LT(float_rank(in_order[i]), float_rank(in_order[i + 1])) << in_order[i];
  for (float f : in_order)
    EXPECT_EQ(std::bit_cast<uint32_t>(float_of_rank(float_rank(f))), std::bit_cast<uint32_t>(f));
}

TEST(SahBins, SweepAreaIsBBoxHalfAreaBitForBit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1e3f, 1e3f);
  const float specials[] = {kNaN, kFloatInf, -kFloatInf, 0.0f, -0.0f, 1e-45f, 3e38f};
  for (int trial = 0; trial < 20000; ++trial) {
    BBox b;
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = u(rng);
      b.hi[a] = trial % 5 == 0 ? u(rng) : b.lo[a] + std::abs(u(rng));  // some empty along an axis
      if (trial % 7 == 0) (rng() % 2 ? b.lo[a] : b.hi[a]) = specials[rng() % std::size(specials)];
    }
    if (trial == 0) b = BBox{};  // the empty box
    const sse::Float4 lo = sse::Float4::set(b.lo.x, b.lo.y, b.lo.z, 0.0f);
    const sse::Float4 hi = sse::Float4::set(b.hi.x, b.hi.y, b.hi.z, 0.0f);
    const float expected = b.half_area(), got = sse::half_area(lo, hi);
    ASSERT_EQ(std::bit_cast<uint32_t>(got), std::bit_cast<uint32_t>(expected))
        << "lo " << b.lo.x << "," << b.lo.y << "," << b.lo.z << " hi " << b.hi.x << "," << b.hi.y << ","
        << b.hi.z;
  }
}

TEST(SahBins, WithLaneReplacesOneLaneOnly) {  // the spatial-split search's clipped reference boxes
  const sse::Float4 v = sse::Float4::set(1.0f, -2.0f, kNaN, -0.0f);
  for (int lane = 0; lane < 4; ++lane) {
    alignas(16) float got[4], was[4];
    v.with_lane(lane, 7.5f).store(got);
    v.store(was);
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(std::bit_cast<uint32_t>(got[k]), std::bit_cast<uint32_t>(k == lane ? 7.5f : was[k]))
          << "lane " << lane << ", element " << k;
  }
}

}  // namespace
}  // namespace rayvec
