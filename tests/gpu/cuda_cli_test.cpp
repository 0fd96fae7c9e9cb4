// --device on `visibility` and `hits`, and `rayvec info`'s CUDA lines, end to end. Without a GPU
// (or without CUDA in the build) --device cuda must fail cleanly and write nothing; the runs that
// compare the GPU with the CPU skip, saying why, where no device is found.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gpu/cuda_backend.h"
#include "platform/isa.h"
#include "test_support.h"

namespace rayvec {
namespace {

const std::string kData = RAYVEC_TEST_DATA;

bool have_device() { return gpu::cuda_built() && !gpu::cuda_system().devices.empty(); }

// A unit cube, 12 triangles sharing vertices.
void write_cube(const std::string& path) {
  test::write_file(path,
                   "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                   "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 7 3\nf 4 8 7\n"
                   "f 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n");
}

std::string visibility_args() {
  return "visibility --verts " + kData + "/visibility/verts.csv --faces " + kData + "/visibility/meshes.csv";
}

TEST(CudaCli, DeviceCudaWithoutGpuFailsCleanlyAndWritesNothing) {
  if (have_device()) GTEST_SKIP() << "a CUDA device is present: CudaCli.DeviceCudaMatchesCpu covers it";
  const std::string dir = test::temp_dir("cuda_none");
  test::write_file(dir + "/old.txt", "old\n");
  test::write_file(dir + "/rays.csv", "0,0,-5,0,0,1\n");
  write_cube(dir + "/cube.obj");
  for (const char* cmd : {"visibility", "hits"}) {
    const std::string input = std::string(cmd) == "visibility"
                                  ? visibility_args()
                                  : "hits --mesh " + dir + "/cube.obj --rays " + dir + "/rays.csv";
    const auto r = test::run_cli(input + " --device cuda -o " + dir + "/old.txt");
    if (gpu::cuda_built()) {
      EXPECT_EQ(r.status, 1) << r.err;
      EXPECT_NE(r.err.find("no CUDA device found"), std::string::npos) << r.err;
    } else {
      EXPECT_EQ(r.status, 2) << r.err;
      EXPECT_NE(r.err.find("built without CUDA"), std::string::npos) << r.err;
    }
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(test::read_file(dir + "/old.txt"), "old\n") << cmd << ": the old output must stay";
    int files = 0;
    for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 3) << cmd << ": no temporary left behind";
  }
}

TEST(CudaCli, BadDeviceOptionsAreUsageErrors) {
  const auto bad_device = test::run_cli(visibility_args() + " --device gpu");
  EXPECT_EQ(bad_device.status, 2);
  EXPECT_NE(bad_device.err.find("--device: unknown 'gpu' (choose cpu or cuda)"), std::string::npos);
  const auto bad_tile = test::run_cli(visibility_args() + " --device cuda --tile 32");
  EXPECT_EQ(bad_tile.status, 2);
  EXPECT_NE(bad_tile.err.find("--tile: must be between 64 and 1024"), std::string::npos) << bad_tile.err;
  const auto bad_kernel = test::run_cli(visibility_args() + " --gpu-kernel texture");
  EXPECT_EQ(bad_kernel.status, 2);
  EXPECT_NE(bad_kernel.err.find("choose global, shared or soa"), std::string::npos) << bad_kernel.err;
  const auto paper = test::run_cli(visibility_args() + " --device cuda --intersector paper");
  EXPECT_EQ(paper.status, 2);
  EXPECT_NE(paper.err.find(gpu::cuda_built() ? "is CPU-only" : "built without CUDA"), std::string::npos)
      << paper.err;
}

TEST(CudaCli, InfoListsTheCudaBuild) {
  const auto r = test::run_cli("info");
  ASSERT_EQ(r.status, 0) << r.err;
  if (gpu::cuda_built()) {
    EXPECT_NE(r.out.find(std::string("cuda: built with CUDA ") + gpu::cuda_toolkit_version()),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("cuda device"), std::string::npos) << r.out;
  } else {
    EXPECT_NE(r.out.find("cuda: not built"), std::string::npos) << r.out;
  }
}

// Every kernel and device intersector against the CPU on the hand-checked visibility files and on
// the rays of a cube: the same bytes out (hits against the AVX2/AVX-512 CPU kernels, whose rounding
// the device shares).
TEST(CudaCli, DeviceCudaMatchesCpu) {
  if (!gpu::cuda_built()) GTEST_SKIP() << "built without CUDA (configure with -DRAYVEC_CUDA=ON)";
  if (!have_device()) GTEST_SKIP() << "no CUDA device found";
  if (!isa_supported(Isa::avx2)) GTEST_SKIP() << "this CPU lacks AVX2, whose rounding the device shares";
  const std::string dir = test::temp_dir("cuda_cli");
  std::string rays;
  for (int i = 0; i < 200; ++i)
    rays += std::to_string(-2.0 + 0.02 * i) + "," + std::to_string(0.3 - 0.003 * i) + ",-5,0.01,0.02,1\n";
  test::write_file(dir + "/rays.csv", rays);
  write_cube(dir + "/cube.obj");
  const std::string hits = "hits --mesh " + dir + "/cube.obj --rays " + dir + "/rays.csv --isa avx2";
  for (const char* i : {"mt", "mt64", "watertight", "watertight64"}) {
    const std::string is = std::string(" --intersector ") + i;
    const auto cpu_vis = test::run_cli(visibility_args() + is);
    const auto cpu_hits = test::run_cli(hits + is);
    const auto cpu_any = test::run_cli(hits + is + " --any");
    ASSERT_EQ(cpu_vis.status, 0) << cpu_vis.err;
    ASSERT_EQ(cpu_hits.status, 0) << cpu_hits.err;
    for (const char* k : {"global", "shared", "soa"})
      for (const char* tile : {"64", "1024"}) {
        const std::string dev = std::string(" --device cuda --gpu-kernel ") + k + " --tile " + tile;
        const auto vis = test::run_cli(visibility_args() + is + dev);
        EXPECT_EQ(vis.status, 0) << vis.err;
        EXPECT_EQ(vis.out, cpu_vis.out) << i << " " << k << " " << tile;
        const auto h = test::run_cli(hits + is + dev);
        EXPECT_EQ(h.out, cpu_hits.out) << i << " " << k << " " << tile;
        const auto any = test::run_cli(hits + is + dev + " --any");
        EXPECT_EQ(any.out, cpu_any.out) << i << " " << k << " " << tile;
      }
  }
}

}  // namespace
}  // namespace rayvec
