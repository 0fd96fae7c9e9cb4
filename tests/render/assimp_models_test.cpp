// Real OBJ files: every model of Debian's assimp-testmodels renders (exit 0), or is rejected cleanly
// (exit 2) where tinyobjloader itself cannot read it; spider.obj renders with its textures
// (`map_Kd .\wal67ar_small.jpg`) like its reference, made with:
//   rayvec render /usr/share/assimp/models/OBJ/spider.obj -o tests/data/images/spider.png --width 96 --height
//   72 --spp 1
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "test_support.h"

namespace rayvec {
namespace {

const std::string kModels = "/usr/share/assimp/models/OBJ/";

TEST(AssimpModels, EveryObjRendersOrIsRejectedCleanly) {
  if (!std::filesystem::exists(kModels)) GTEST_SKIP() << "package assimp-testmodels is not installed";
  // Rejected on purpose: UTF-16, a malformed number, and files with no faces.
  const std::set<std::string> rejected = {"box_UTF16BE.obj", "number_formats.obj", "point_cloud.obj",
                                          "testline.obj", "testpoints.obj"};
  const std::string dir = test::temp_dir("assimp_models");
  int rendered = 0;
  for (const auto& e : std::filesystem::directory_iterator(kModels)) {
    if (e.path().extension() != ".obj") continue;
    const std::string name = e.path().filename().string();
    const auto r =
        test::run_cli("render -q '" + e.path().string() + "' --width 16 --height 12 -o " + dir + "/o.png");
    EXPECT_EQ(r.status, rejected.count(name) ? 2 : 0) << name << ": " << r.err;
    rendered += r.status == 0;
  }
  EXPECT_GE(rendered, 15);
}

TEST(AssimpModels, SpiderRendersWithItsTextures) {
  if (!std::filesystem::exists(kModels + "spider.obj"))
    GTEST_SKIP() << "package assimp-testmodels is not installed";
  const std::string dir = test::temp_dir("assimp_spider");
  const auto r = test::run_cli("render '" + kModels + "spider.obj' -o " + dir +
                               "/spider.png --width 96 --height 72 --spp 1 --quiet --strict");
  ASSERT_EQ(r.status, 0) << r.err;  // --strict: every texture was found and decoded
  const auto cmp =
      test::run_cli("compare '" + std::string(RAYVEC_SOURCE_DIR) + "/tests/data/images/spider.png' " + dir +
                    "/spider.png --max-rmse 0.01 --max-pixel 0.25");
  EXPECT_EQ(cmp.status, 0) << cmp.out << cmp.err;
}

}  // namespace
}  // namespace rayvec
