// Golden images: every scene in scenes/ rendered small on every ISA the CPU has and compared with the
// reference in tests/data/images/ through `rayvec compare`, the way a user writes a regression test.
// Thresholds (PNG values, sRGB-encoded in [0,1]): RMSE <= 0.01 and no pixel off by more than 0.25 —
// loose enough for FMA/no-FMA rounding at silhouette pixels across ISAs, tight enough that a wrong
// light, material or effect moves the RMSE far beyond it (see GoldenScenes.CompareCatchesAWrongImage).
// References were made with: rayvec render scenes/<name>.json --width 96 --height 72 --spp 1 (the
// bare OBJ scenes/models/painted_sphere.obj too: smoothing groups and vertex colours).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "platform/isa.h"
#include "test_support.h"

namespace rayvec {
namespace {

using test::run_cli;

const char* const kScenes[] = {"whitted",    "cornell_box", "shadows",
                               "reflection", "refraction",  "painted_sphere"};

std::string scene(const std::string& name) {
  const std::string dir = std::string(RAYVEC_SOURCE_DIR) + "/scenes/";
  return name == "painted_sphere" ? dir + "models/" + name + ".obj" : dir + name + ".json";
}
std::string reference(const std::string& name) {
  return std::string(RAYVEC_SOURCE_DIR) + "/tests/data/images/" + name + ".png";
}

std::string render_small(const std::string& name, Isa isa, const std::string& dir) {
  const std::string out = dir + "/" + name + "_" + isa_name(isa) + ".png";
  const auto r = run_cli("render '" + scene(name) + "' -o '" + out +
                         "' --width 96 --height 72 --spp 1 --quiet --isa " + isa_name(isa));
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

TEST(GoldenScenes, EverySceneMatchesItsReferenceOnEveryIsa) {
  const std::string dir = test::temp_dir("golden");
  for (Isa isa : kAllIsas) {
    if (!isa_supported(isa)) {
      std::printf("[ skipped ] %s: CPU lacks it\n", isa_name(isa));
      continue;
    }
    for (const char* name : kScenes) {
      SCOPED_TRACE(std::string(name) + " on " + isa_name(isa));
      const std::string out = render_small(name, isa, dir);
      const auto cmp =
          run_cli("compare '" + reference(name) + "' '" + out + "' --max-rmse 0.01 --max-pixel 0.25");
      EXPECT_EQ(cmp.status, 0) << cmp.out << cmp.err;
    }
  }
}

TEST(GoldenScenes, CompareCatchesAWrongImage) {
  const std::string dir = test::temp_dir("golden_wrong");
  const std::string out = render_small("reflection", best_isa(), dir);
  const auto cmp =
      run_cli("compare '" + reference("shadows") + "' '" + out + "' --max-rmse 0.01 --max-pixel 0.25");
  EXPECT_EQ(cmp.status, 1) << cmp.out;
  EXPECT_NE(cmp.out.find("rmse"), std::string::npos);
}

// Simulate only what the scene calls for: ray counts per kind from --stats-json.
long ray_count(const std::string& json, const std::string& kind) {
  const auto at = json.find("\"" + kind + "\"");
  if (at == std::string::npos) return -1;
  return std::stol(json.substr(json.find(':', at) + 1));
}

TEST(GoldenScenes, ScenesSpawnOnlyTheRaysTheirMaterialsNeed) {
  const std::string dir = test::temp_dir("effects");
  struct Expect {
    const char* scene;
    bool reflection, refraction;
  };
  for (const Expect e : {Expect{"shadows", false, false}, Expect{"cornell_box", false, false},
                         Expect{"reflection", true, false}, Expect{"refraction", true, true}}) {
    SCOPED_TRACE(e.scene);
    const std::string stats = dir + "/" + e.scene + ".json";
    const auto r = run_cli("render '" + scene(e.scene) + "' -o '" + dir +
                           "/x.png' --width 48 "
                           "--height 36 --spp 1 --quiet --stats-json '" +
                           stats + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = test::read_file(stats);
    EXPECT_EQ(ray_count(json, "primary"), 48 * 36);
    EXPECT_GT(ray_count(json, "shadow"), 0);
    if (e.reflection)
      EXPECT_GT(ray_count(json, "reflection"), 0);
    else
      EXPECT_EQ(ray_count(json, "reflection"), 0);
    if (e.refraction)
      EXPECT_GT(ray_count(json, "refraction"), 0);
    else
      EXPECT_EQ(ray_count(json, "refraction"), 0);
    EXPECT_NE(json.find("\"seconds\""), std::string::npos);
  }
}

TEST(GoldenScenes, UnknownSceneKeyIsAnInputErrorNamingIt) {
  const std::string dir = test::temp_dir("typo");
  std::string text = test::read_file(scene("shadows"));
  text.insert(text.find('{') + 1, " \"backgroud\": [0, 0, 0],");
  test::write_file(dir + "/typo.json", text);
  const auto r = run_cli("render '" + dir + "/typo.json' -o '" + dir + "/x.png' --quiet");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("backgroud"), std::string::npos) << r.err;
  EXPECT_FALSE(std::ifstream(dir + "/x.png").good()) << "no output on bad input";
}

TEST(GoldenScenes, UnwritableOutputFailsBeforeRendering) {
  // --spp 4096 at full size would take minutes: exiting at once shows the check comes first.
  const auto r = run_cli("render '" + scene("whitted") + "' -o /nonexistent-dir/x.png --spp 4096 --quiet");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot write /nonexistent-dir/x.png"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rayvec
