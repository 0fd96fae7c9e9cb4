// The packet tests' check: closest_stream must give, ray by ray, exactly what closest() and brute
// force give — same id and bit-identical t, u, v.
#pragma once
#include <bit>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"

namespace rayvec::test {

// closest_stream of `bvh` over `rays` against bvh.closest() and brute.closest() per ray; stops at
// the first ray that differs; returns the number of hits.
inline int expect_stream_exact(const BvhAccelerator& bvh, const BruteForce& brute,
                               const std::vector<Ray>& rays) {
  auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
  std::vector<Hit> stream(rays.size());
  bvh.closest_stream(rays.data(), stream.data(), rays.size());
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    for (const Hit& want : {bvh.closest(rays[i]), brute.closest(rays[i])}) {
      EXPECT_EQ(want.tri, stream[i].tri) << "ray " << i;
      EXPECT_EQ(bits(want.t), bits(stream[i].t)) << "ray " << i << ": " << want.t << " vs " << stream[i].t;
      EXPECT_EQ(bits(want.u), bits(stream[i].u)) << "ray " << i;
      EXPECT_EQ(bits(want.v), bits(stream[i].v)) << "ray " << i;
      if (::testing::Test::HasFailure()) return hits;
    }
    hits += stream[i].hit();
  }
  return hits;
}

}  // namespace rayvec::test
