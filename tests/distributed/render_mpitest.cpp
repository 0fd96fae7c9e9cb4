// `mpirun -np 2 rayvec render`: the image (every AOV channel) is the one-process image bit for bit,
// the ray counts are the same, and rank 0 alone prints, with the per-rank load.
#include <gtest/gtest.h>

#include <cstring>

#include "distributed/mpi_run.h"
#include "image/image_io.h"

namespace rayvec {
namespace {

const std::string kScene = std::string(RAYVEC_SOURCE_DIR) + "/scenes/whitted.json";

TEST(MpiRender, ImageIsBitIdenticalToOneProcess) {
  const std::string dir = test::temp_dir("mpi_render");
  const std::string args =
      "'" + kScene + "' --width 150 --height 90 --spp 2 --aov depth,normal,id,cost,bounces --stats";
  const auto one = test::run_cli("render " + args + " -o '" + dir + "/one.exr'");
  ASSERT_EQ(one.status, 0) << one.err;
  const auto two = test::run_mpi("render " + args + " -o '" + dir + "/two.exr'");
  ASSERT_EQ(two.status, 0) << two.err;
  const Image a = read_image(dir + "/one.exr"), b = read_image(dir + "/two.exr");
  EXPECT_EQ(a.channels, b.channels);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
  // The same rays, counted across the ranks; rank 0 alone prints (one "wrote" line).
  const auto line = [](const std::string& out, const std::string& start) {
    const std::size_t at = out.find(start);
    return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
  };
  EXPECT_EQ(line(one.out, "rays: "), line(two.out, "rays: "));
  EXPECT_EQ(line(one.out, "camera rays that hit: "), line(two.out, "camera rays that hit: "));
  EXPECT_NE(line(two.out, "camera rays that hit: "), "") << two.out;
  EXPECT_EQ(test::count_of(two.out, "wrote "), 1) << two.out;
  EXPECT_NE(two.out.find("ranks: 2; rays per rank: "), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("load imbalance (slowest / mean): "), std::string::npos) << two.out;
  EXPECT_EQ(test::entries_of(dir), "one.exr two.exr ") << "a temporary was left";
}

// More ranks than tiles: the ranks left without a tile finish cleanly.
TEST(MpiRender, MoreRanksThanTiles) {
  const std::string dir = test::temp_dir("mpi_render_small");
  const std::string args = "'" + kScene + "' --width 16 --height 16 -q";
  ASSERT_EQ(test::run_cli("render " + args + " -o '" + dir + "/one.png'").status, 0);
  const auto three = test::run_mpi("render " + args + " -o '" + dir + "/three.png'", "", "", 3);
  ASSERT_EQ(three.status, 0) << three.err;
  const Image a = read_image(dir + "/one.png"), b = read_image(dir + "/three.png");
  EXPECT_EQ(a.pixels, b.pixels);
}

TEST(MpiCluster, CommandsThatDoNotDistributeAreRefused) {
  const std::string mesh = std::string(RAYVEC_SOURCE_DIR) + "/scenes/models/cube.obj";
  for (const std::string& command : {std::string("info"), "bench rays '" + mesh + "' --size 8x8"}) {
    const auto r = test::run_mpi(command);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(test::count_of(r.err, "this command does not run across ranks"), 1) << r.err;
    EXPECT_EQ(r.out, "") << command;
  }
}

}  // namespace
}  // namespace rayvec
