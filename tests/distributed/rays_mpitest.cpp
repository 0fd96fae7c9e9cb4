// `mpirun -np 2 rayvec hits | visibility`: answers gathered in input order, byte for byte what one
// process writes, with rank 0 reading standard input.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "distributed/mpi_run.h"

namespace rayvec {
namespace {

std::string random_rays(int n) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  std::string csv = "ox,oy,oz,dx,dy,dz\n";
  for (int i = 0; i < n; ++i)
    csv += std::to_string(u(rng)) + "," + std::to_string(u(rng)) + ",-2," + std::to_string(0.1f * u(rng)) +
           "," + std::to_string(0.1f * u(rng)) + ",1\n";
  return csv;
}

TEST(MpiHits, ClosestAndAnyHitEqualOneProcess) {
  const std::string dir = test::temp_dir("mpi_hits");
  const std::string mesh = std::string(RAYVEC_SOURCE_DIR) + "/scenes/models/cube.obj";
  test::write_file(dir + "/rays.csv", random_rays(3001));
  for (const std::string any : {"", " --any"}) {
    const std::string args = "hits --mesh '" + mesh + "'" + any;
    const auto one = test::run_cli(args + " --rays '" + dir + "/rays.csv'");
    ASSERT_EQ(one.status, 0) << one.err;
    const auto file = test::run_mpi(args + " --rays '" + dir + "/rays.csv' -o '" + dir + "/two.csv'");
    ASSERT_EQ(file.status, 0) << file.err;
    EXPECT_EQ(test::read_file(dir + "/two.csv"), one.out) << any;
    EXPECT_NE(file.err.find("hits: ranks: 2; rays per rank: 1501, 1500"), std::string::npos) << file.err;
    const auto piped = test::run_mpi(args + " --rays -", "", test::read_file(dir + "/rays.csv"));
    ASSERT_EQ(piped.status, 0) << piped.err;
    EXPECT_EQ(piped.out, one.out) << any;
  }
}

TEST(MpiVisibility, EqualsOneProcess) {
  const std::string data = std::string(RAYVEC_TEST_DATA) + "/visibility";
  const std::string args = "visibility --verts '" + data + "/verts.csv' --faces '" + data + "/meshes.csv'";
  const auto one = test::run_cli(args);
  ASSERT_EQ(one.status, 0) << one.err;
  const auto two = test::run_mpi(args);
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(two.out, one.out);
  EXPECT_EQ(two.out, test::read_file(data + "/expected.txt"));
  EXPECT_EQ(test::count_of(two.err, "faces dropped"), 1) << "warnings from rank 0 only: " << two.err;
}

}  // namespace
}  // namespace rayvec
