// `rayvec bench visibility` at a tiny size: every CPU row runs and passes its check, and the GPU
// rows either pass theirs (with a device) or say why they are absent.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "bench/visibility_bench.h"
#include "gpu/cuda_backend.h"
#include "test_support.h"

namespace rayvec {
namespace {

TEST(CudaBench, VisibilityRowsRunAndCheck) {
  const auto r = test::run_cli("bench visibility --rings 12 --tiles 64,128 --threads 2");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("### 266 vertices × 528 triangles (rings 12;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| CPU brute force, scalar (the study's sequential row) | 1 |"), std::string::npos)
      << r.out;
  EXPECT_EQ(test::count_of(r.out, "MISMATCH"), 0) << r.out;
  // scalar, and each further ISA of this CPU, on 1 and 2 threads, plus the BVH
  EXPECT_GE(test::count_of(r.out, "| ok |"), 5) << r.out;
  if (!gpu::cuda_built())
    EXPECT_NE(r.out.find("absent: built without CUDA"), std::string::npos) << r.out;
  else if (gpu::cuda_system().devices.empty())
    EXPECT_NE(r.out.find("absent: no CUDA device found"), std::string::npos) << r.out;
  else
    EXPECT_EQ(test::count_of(r.out, "| GPU "), 5) << r.out;  // global, shared and soa at two tile sizes
}

TEST(CudaBench, BumpySphereIsClosed) {
  const TriangleMesh m = bumpy_sphere(12);
  EXPECT_EQ(m.positions.size(), 11u * 24u + 2u);
  EXPECT_EQ(m.size(), 4u * 12u * 11u);
  // closed: every edge is shared by exactly two triangles, in opposite directions
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
}

TEST(CudaBench, BadListsAreUsageErrors) {
  const auto r = test::run_cli("bench visibility --tiles 32");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--tiles: '32' is not a comma-separated list of integers from 64 to 1024"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rayvec
