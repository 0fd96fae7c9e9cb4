// Float4 (simd/float4_sse.h) against the scalar rules the BVH builder relies on: min and max return
// the second operand where either is NaN, truncation toward zero, and lane 3 cleared by xyz().
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "simd/float4_sse.h"

namespace rayvec {
namespace {

using sse::Float4;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(Float4Sse, MinMaxKeepTheSecondOperandWhereEitherIsNaN) {
  const Float4 a = Float4::set(1.0f, kNaN, 3.0f, -0.0f), b = Float4::set(2.0f, 5.0f, kNaN, 0.0f);
  float lo[4], hi[4];
  sse::vmin(a, b).store(lo);
  sse::vmax(a, b).store(hi);
  EXPECT_EQ(lo[0], 1.0f);
  EXPECT_EQ(lo[1], 5.0f);
  EXPECT_TRUE(std::isnan(lo[2]));
  EXPECT_FALSE(std::signbit(lo[3]));  // -0 < +0 is false: the second operand
  EXPECT_EQ(hi[0], 2.0f);
  EXPECT_EQ(hi[1], 5.0f);
  EXPECT_TRUE(std::isnan(hi[2]));
  EXPECT_FALSE(std::signbit(hi[3]));
}

TEST(Float4Sse, ArithmeticMatchesScalarLaneByLane) {
  const float x[4] = {1.5f, -2.25f, 1e30f, 0.1f}, y[4] = {0.3f, 7.0f, 1e10f, -0.7f};
  const Float4 a = Float4::load(x), b = Float4::load(y);
  float s[4], d[4], p[4];
  (a + b).store(s);
  (a - b).store(d);
  (a * b).store(p);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(s[i], x[i] + y[i]);
    EXPECT_EQ(d[i], x[i] - y[i]);
    EXPECT_EQ(p[i], x[i] * y[i]);
  }
}

TEST(Float4Sse, TruncatesTowardZeroAndClearsLaneThreeOnRequest) {
  int32_t k[4];
  Float4::set(2.99f, -1.5f, 31.0f, 0.0f).store_truncated(k);
  EXPECT_EQ(k[0], 2);
  EXPECT_EQ(k[1], -1);
  EXPECT_EQ(k[2], 31);
  EXPECT_EQ(k[3], 0);
  float v[4];
  Float4::set(1.0f, 2.0f, 3.0f, kInf).xyz().store(v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[2], 3.0f);
  EXPECT_EQ(v[3], 0.0f);
  EXPECT_FALSE(std::signbit(v[3]));
}

}  // namespace
}  // namespace rayvec
