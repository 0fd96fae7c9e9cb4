// The packets' per-lane rules in SIMD lanes against their scalar definitions, bit for bit, on the
// values where they differ from plain arithmetic: next_up is the next float toward +inf (±0 gives
// the smallest subnormal, −inf the most negative finite value, +inf and NaN stay), and mt_lower is
// tmin·(1 − 2^-20) for tmin > 0, 0 for ±0 and −inf otherwise (NaN included). The packet traversals
// form both in lanes (bvh/packet_any_hit.inl, packet_traversal.inl, packet_leaf.inl); a lane that
// disagreed would move a packet's closed end t <= tmax away from the single ray's. And the two forms
// of the one-origin group test's det orientation, which must agree bit for bit. Every ISA with
// vector lanes; ISAs the CPU lacks are skipped and named.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "platform/isa.h"
#include "simd/lane_rules.h"

namespace rayvec {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNarrow = 1.0f - 0x1p-20f;  // kernels/mt_float.inl's kMtNarrow

std::vector<float> hard_values() {
  const float denorm = std::numeric_limits<float>::denorm_min(), tiny = std::numeric_limits<float>::min();
  const float big = std::numeric_limits<float>::max(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> v = {
      0.0f,  -0.0f,  denorm,    -denorm,   tiny, -tiny, 1.0f, -1.0f, 1.5f,   -1.5f,
      2.0f,  -2.0f,  big,       -big,      kInf, -kInf, nan,  -nan,  1e-30f, std::nextafter(2.0f, 0.0f),
      3e38f, -3e38f, 0x1p-126f, -0x1p-149f};
  std::mt19937 rng(7);
  while (v.size() % 16 != 0 || v.size() < 256) v.push_back(std::bit_cast<float>(uint32_t(rng())));
  return v;
}

void expect_same_bits(float want, float got, float x, const char* rule, Isa isa) {
  if (std::isnan(want)) {
    EXPECT_TRUE(std::isnan(got)) << rule << " " << isa_name(isa) << " of " << x;
  } else {
    EXPECT_EQ(std::bit_cast<uint32_t>(want), std::bit_cast<uint32_t>(got))
        << rule << " " << isa_name(isa) << " of " << x << ": " << want << " wanted, " << got << " got";
  }
}

class LaneRules : public ::testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    if (!isa_supported(GetParam())) GTEST_SKIP() << isa_name(GetParam()) << " is not available on this CPU";
  }
  test::LaneRules rules() const {
    return GetParam() == Isa::avx2 ? test::lane_rules_avx2() : test::lane_rules_avx512();
  }
};

TEST_P(LaneRules, NextUpIsTheNextFloatTowardInfinity) {
  const std::vector<float> in = hard_values();
  std::vector<float> out(in.size());
  rules().next_up(in.data(), out.data(), int(in.size()));
  for (std::size_t i = 0; i < in.size(); ++i)
    expect_same_bits(std::nextafter(in[i], kInf), out[i], in[i], "next_up", GetParam());
}

TEST_P(LaneRules, MtLowerNarrowsPositiveTminKeepsZeroAndDropsTheRest) {
  const std::vector<float> in = hard_values();
  std::vector<float> out(in.size());
  rules().mt_lower(in.data(), out.data(), int(in.size()));
  for (std::size_t i = 0; i < in.size(); ++i) {
    const float x = in[i];
    const float want = x > 0.0f ? x * kNarrow : x == 0.0f ? 0.0f : -kInf;
    expect_same_bits(want, out[i], x, "mt_lower", GetParam());
  }
}

// A uniform forward packet's hull (PacketForward::hull, bvh/simd/packet_lanes.inl) bounds the lanes
// asked for with their own extremes, bit for bit: a hull narrower than a lane drops children that
// lane enters, a wider one tests more than it must. Its nr and fr bounds are 1/d's extremes times
// 1 ∓ eps, equal to the extremes of the lanes' own products only because rounding a product with a
// positive constant is monotonic; the directions run from subnormal reciprocals to 2^60, both signs.
TEST_P(LaneRules, PacketHullIsTheExtremesOfItsLanes) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<unsigned> masks = {0xffffu, 1u, 0x8000u, 0x0ff0u, 0x5555u};
  for (int i = 0; i < 20; ++i) masks.push_back((unsigned(rng()) & 0xffffu) | 1u << (rng() % 16));
  for (int trial = 0; trial < 200; ++trial) {
    alignas(64) float soa[8][16];
    for (int a = 0; a < 3; ++a) {
      const float sign = rng() % 2 ? -1.0f : 1.0f;
      for (int k = 0; k < 16; ++k) {
        soa[a][k] = (unit(rng) - 0.5f) * std::ldexp(1.0f, int(rng() % 40) - 20);
        // 1/d from 2^-127 (subnormal) to 2^60, in the axis' one sign
        soa[3 + a][k] = sign * (1.0f + unit(rng)) * std::ldexp(1.0f, int(rng() % 188) - 127);
      }
    }
    for (int k = 0; k < 16; ++k) {
      soa[6][k] = rng() % 3 ? 0.0f : unit(rng);
      soa[7][k] = rng() % 4 ? 1.0f + 100.0f * unit(rng) : kInf;
    }
    const float eps = trial % 2 ? 0x1p-18f : 0x1p-20f;
    for (unsigned lanes : masks) {
      test::PacketHullLanes got;
      rules().packet_hull(&soa[0][0], lanes, eps, &got);
      // the lanes' extremes: lowest for nr_lo, fr_lo, kf_lo and tmin, highest for the others
      const int row[20] = {0, 1, 2, 0, 1, 2, 3, 4, 5, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13};
      const bool lowest[20] = {1, 1, 1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0};
      for (int j = 0; j < 20; ++j) {
        float want = lowest[j] ? kInf : -kInf;
        for (int k = 0; k < 16; ++k)
          if (lanes >> k & 1u)
            want = lowest[j] ? std::min(want, got.lanes[row[j]][k]) : std::max(want, got.lanes[row[j]][k]);
        EXPECT_EQ(std::bit_cast<uint32_t>(want), std::bit_cast<uint32_t>(got.hull[j]))
            << "hull bound " << j << ", lanes " << std::hex << lanes << ", " << isa_name(GetParam()) << ": "
            << want << " wanted, " << got.hull[j] << " got";
      }
    }
  }
}

// The offsets k = o·r' a forward packet subtracts in every box test, and the hull's, are never
// subnormal where the origin's coordinate is 0 or normal: a camera on an axis plane (o = 0) gives the
// outward move's floor, the smallest normal float, not one subnormal step — a subnormal operand
// costs Intel's FMAs a microcode assist in every box test. And they stay outward of the product:
// kn above o·nr, kf below o·fr.
TEST_P(LaneRules, PacketOffsetsOfAnOriginOnAnAxisPlaneAreNormal) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 50; ++trial) {
    alignas(64) float soa[8][16];
    for (int a = 0; a < 3; ++a) {
      const float sign = rng() % 2 ? -1.0f : 1.0f;
      for (int k = 0; k < 16; ++k) {
        soa[a][k] = a == trial % 3 || rng() % 4 == 0 ? (rng() % 2 ? 0.0f : -0.0f) : 4.0f * unit(rng) - 2.0f;
        soa[3 + a][k] = sign * (0.5f + 64.0f * unit(rng));
      }
    }
    for (int k = 0; k < 16; ++k) {
      soa[6][k] = 0.0f;
      soa[7][k] = kInf;
    }
    test::PacketHullLanes got;
    rules().packet_hull(&soa[0][0], 0xffffu, 0x1p-20f, &got);
    const auto normal_or_zero = [](float x) { return x == 0.0f || std::abs(x) >= 0x1p-126f; };
    for (int a = 0; a < 3; ++a) {
      for (int k = 0; k < 16; ++k) {
        const float kn = got.lanes[6 + a][k], kf = got.lanes[9 + a][k];
        EXPECT_TRUE(normal_or_zero(kn) && normal_or_zero(kf))
            << "axis " << a << " lane " << k << ", " << isa_name(GetParam()) << ": kn " << kn << ", kf "
            << kf;
        const double o = soa[a][k];
        EXPECT_GT(double(kn), o * double(got.lanes[a][k])) << "axis " << a << " lane " << k;
        EXPECT_LT(double(kf), o * double(got.lanes[3 + a][k])) << "axis " << a << " lane " << k;
      }
      EXPECT_TRUE(normal_or_zero(got.hull[12 + a]) && normal_or_zero(got.hull[15 + a]))
          << "hull axis " << a << ", " << isa_name(GetParam());
    }
  }
}

// det's orientation by an FMA with sign_one(det) = ±1 (Intel's table) gives the bits of the sign
// flip and add (the others'): s·x is exact, and both round the same sum once; with 0 added, −0
// becomes +0 either way. A NaN stays a NaN. The one-origin group test takes one form or the other
// and must pass the same lanes with either.
TEST_P(LaneRules, DetSignByFmaIsTheFlipAndAddBitForBit) {
  std::vector<float> x = hard_values(), det = hard_values();
  std::mt19937 rng(11);
  std::shuffle(det.begin(), det.end(), rng);
  const int n = int(x.size());
  for (float slack : {0.0f, 0x1p-30f, 1.0f, 3e38f}) {
    std::vector<float> out(6 * std::size_t(n));
    rules().det_sign_forms(x.data(), det.data(), slack, out.data(), n);
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < 6; r += 2) {
        const float fused = out[std::size_t(r * n + i)], flipped = out[std::size_t((r + 1) * n + i)];
        if (std::isnan(flipped))
          EXPECT_TRUE(std::isnan(fused)) << isa_name(GetParam()) << " form " << r << " of " << x[i];
        else
          EXPECT_EQ(std::bit_cast<uint32_t>(flipped), std::bit_cast<uint32_t>(fused))
              << isa_name(GetParam()) << " form " << r << ": x " << x[i] << ", det " << det[i] << ", slack "
              << slack << ": " << flipped << " flipped, " << fused << " fused";
      }
  }
}

INSTANTIATE_TEST_SUITE_P(VectorIsas, LaneRules, ::testing::Values(Isa::avx2, Isa::avx512),
                         [](const auto& info) { return std::string(isa_name(info.param)); });

}  // namespace
}  // namespace rayvec
