// The packet's setup (PacketLanes::load_rays, bvh_closest_packet): the rays of a packet are
// transposed in SIMD and the untraceable ones (NaN or infinite origin or direction, NaN tmin or
// tmax) dropped there, not by the caller; every lane's hit is overwritten, whatever the caller's
// array held. Each lane must still equal its single ray and brute force, bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"
#include "bvh_cases.h"
#include "bvh_scenes.h"

namespace rayvec {
namespace {

class BvhPacketSetup : public test::BvhCaseTest {};

// Camera rays from one eye, in groups of 16 (a 4×4 tile, one packet on AVX2 and AVX-512).
std::vector<Ray> tile_rays(int tiles) {
  std::vector<Ray> rays;
  for (int t = 0; t < tiles; ++t)
    for (int k = 0; k < 16; ++k) {
      const float x = float(t % 8) * 0.1f + float(k % 4) * 0.02f - 0.4f;
      const float y = float(t / 8) * 0.1f + float(k / 4) * 0.02f - 0.4f;
      rays.push_back(Ray{{0.05f, -0.02f, 2.5f}, {x, y, -1.0f}});
    }
  return rays;
}

void expect_stream_exact(const TriangleMesh& mesh, const TraceConfig& config, int width,
                         const std::vector<Ray>& rays) {
  BvhOptions options;
  options.width = width;
  const BvhAccelerator bvh(mesh, config, options);
  const BruteForce brute(mesh, config);
  std::vector<Hit> stream(rays.size(), Hit{0.5f, 1.0f, 2.0f, 7});  // garbage to be overwritten
  bvh.closest_stream(rays.data(), stream.data(), rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i)
    for (const Hit& want : {bvh.closest(rays[i]), brute.closest(rays[i])}) {
      ASSERT_EQ(want.tri, stream[i].tri) << "ray " << i;
      ASSERT_EQ(std::bit_cast<uint32_t>(want.t), std::bit_cast<uint32_t>(stream[i].t)) << "ray " << i;
      ASSERT_EQ(std::bit_cast<uint32_t>(want.u), std::bit_cast<uint32_t>(stream[i].u)) << "ray " << i;
      ASSERT_EQ(std::bit_cast<uint32_t>(want.v), std::bit_cast<uint32_t>(stream[i].v)) << "ray " << i;
    }
}

TEST_P(BvhPacketSetup, UntraceableLanesMissAndTheOthersMatchSingleRays) {
  const TriangleMesh soup = test::random_soup(1500, 0.2f, 31);
  std::vector<Ray> rays = tile_rays(64);
  const float inf = INFINITY, nan = std::nanf("");
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray& r = rays[i];
    switch ((i * 7 + i / 16) % 11) {  // a different mix of lanes in every packet
      case 0: r.org.x = inf; break;
      case 1: r.org.z = -inf; break;
      case 2: r.dir.y = nan; break;
      case 3: r.dir.z = -inf; break;
      case 4: r.tmin = nan; break;
      case 5: r.tmax = nan; break;
      case 6: r.tmin = -inf; break;  // traceable: an infinite interval end is allowed
      default: break;
    }
  }
  expect_stream_exact(soup, config(), GetParam().width, rays);
  const BvhAccelerator bvh(soup, config());
  for (const Ray& r : rays) hits += bvh.closest(r).hit();
  EXPECT_GT(hits, 300);  // the clean lanes do hit
}

// Streams whose length is not a multiple of the packet width end in a partial packet (or a single
// ray), whose missing lanes must be neither read nor written.
TEST_P(BvhPacketSetup, PartialPacketsAtTheEndOfAStream) {
  const TriangleMesh soup = test::random_soup(1500, 0.2f, 32);
  for (std::size_t n : {1u, 2u, 3u, 7u, 9u, 15u, 17u, 18u, 31u}) {
    const std::vector<Ray> all = tile_rays(2);
    expect_stream_exact(soup, config(), GetParam().width, std::vector<Ray>(all.begin(), all.begin() + n));
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsasWidths, BvhPacketSetup,
                         ::testing::ValuesIn(test::bvh_cases({Intersector::mt, Intersector::paper})),
                         test::bvh_case_name);

}  // namespace
}  // namespace rayvec
