// `rayvec trace` and the teaching AOVs end to end: the tree's text and JSON on the default scene,
// the traced pixel value equal to the rendered image's, `--aov cost,bounces` channels with
// plausible values, heatmap PNGs with their legend, and bad input exiting 2 with a clear message.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "image/image_io.h"
#include "render/heatmap.h"
#include "test_support.h"

namespace rayvec {
namespace {

const std::string kScene = std::string(RAYVEC_SOURCE_DIR) + "/scenes/whitted.json";
const std::string kSmall = "'" + kScene + "' --width 64 --height 48";
// At 64×48: (24, 22) sees the mirror sphere, (40, 24) the glass sphere, (2, 2) the sky, (32, 45)
// the checkerboard.

int channel(const Image& img, const std::string& name) {
  for (int c = 0; c < img.nchannels(); ++c)
    if (img.channels[c] == name) return c;
  ADD_FAILURE() << "no channel " << name;
  return 0;
}

Vec3f json_pixel_value(const std::string& json) {
  const std::size_t at = json.find("\"pixel_value\": [");
  EXPECT_NE(at, std::string::npos) << json;
  Vec3f v{};
  if (at != std::string::npos)
    std::sscanf(json.c_str() + at, "\"pixel_value\": [%f, %f, %f]", &v.x, &v.y, &v.z);
  return v;
}

TEST(TraceCli, TextTreeNamesKindsHitsAndStops) {
  const auto r = test::run_cli("trace " + kSmall + " --pixel 40,24 --max-depth 3");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* s :
       {"camera ray, depth 0, weight 1", "  shadow ray to light 0", "  reflection ray, depth 1",
        "  refraction ray, depth 1", "hits triangle", "of object 2", "stops: miss",
        "ray not traced: max depth reached", "pixel value (mean of 4 samples)"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST(TraceCli, JsonPixelValueEqualsTheRenderedPixel) {
  const std::string dir = test::temp_dir("trace_json");
  ASSERT_EQ(test::run_cli("render " + kSmall + " -q -o " + dir + "/w.exr").status, 0);
  const Image img = read_image(dir + "/w.exr");
  for (auto [x, y] : {std::pair{24, 22}, {40, 24}, {2, 2}, {32, 45}}) {
    const std::string at = std::to_string(x) + "," + std::to_string(y);
    const auto r = test::run_cli("trace " + kSmall + " --pixel " + at + " --sample 1 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const Vec3f v = json_pixel_value(r.out);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(v[c], img.at(x, y, c)) << at << " channel " << c;
    EXPECT_NE(r.out.find("\"pixel\": [" + std::to_string(x) + ", " + std::to_string(y) + "], \"sample\": 1"),
              std::string::npos);
    EXPECT_NE(r.out.find("\"kind\": \"camera\""), std::string::npos);
  }
  const auto sky = test::run_cli("trace " + kSmall + " --pixel 2,2 --json");
  EXPECT_NE(sky.out.find("\"hit\": null"), std::string::npos) << sky.out;
  EXPECT_NE(sky.out.find("\"stop\": [\"miss\"]"), std::string::npos) << sky.out;
  const auto glass = test::run_cli("trace " + kSmall + " --pixel 40,24 --json");
  for (const char* s : {"\"kind\": \"refraction\"", "\"kind\": \"reflection\"", "\"kind\": \"shadow\"",
                        "\"material_name\": ", "\"reason\": \"contribution_cutoff\""})
    EXPECT_NE(glass.out.find(s), std::string::npos) << s;
}

// A bare OBJ is framed and lit by the same defaults (and --view) in trace as in render.
TEST(TraceCli, BareObjWithAViewMatchesTheRender) {
  const std::string dir = test::temp_dir("trace_obj");
  const std::string obj =
      "'" + std::string(RAYVEC_SOURCE_DIR) + "/scenes/models/sphere.obj' --width 40 --height 30";
  ASSERT_EQ(test::run_cli("render " + obj + " --view top -q -o " + dir + "/s.exr").status, 0);
  const Image img = read_image(dir + "/s.exr");
  const auto r = test::run_cli("trace " + obj + " --view top --pixel 20,15 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Vec3f v = json_pixel_value(r.out);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(v[c], img.at(20, 15, c)) << c;
  EXPECT_NE(r.out.find("\"kind\": \"shadow\""), std::string::npos) << r.out;  // the light at the eye
}

TEST(TraceCli, CostAndBouncesAovsArePlausibleAndHeatmapsHaveALegend) {
  const std::string dir = test::temp_dir("trace_aov");
  const auto r =
      test::run_cli("render " + kSmall + " --spp 1 -o " + dir + "/w.exr --aov cost,bounces --heatmap");
  ASSERT_EQ(r.status, 0) << r.err;
  const Image img = read_image(dir + "/w.exr");
  ASSERT_EQ(img.nchannels(), 6);
  const int nodes = channel(img, "cost.nodes"), tris = channel(img, "cost.triangles"),
            bounces = channel(img, "bounces");
  EXPECT_GT(img.at(24, 22, tris), img.at(2, 2, tris));  // more triangles tested over geometry than sky
  EXPECT_GT(img.at(40, 24, nodes), img.at(2, 2, nodes));
  EXPECT_EQ(img.at(2, 2, bounces), 0.0f);    // background: the camera ray only
  EXPECT_GE(img.at(24, 22, bounces), 1.0f);  // mirror: at least one bounce
  EXPECT_GE(img.at(40, 24, bounces), 2.0f);  // glass: in and out
  for (const char* name : {"nodes", "triangles", "bounces"}) {
    const std::string png = dir + "/w." + name + ".png";
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    const Image h = read_image(png);
    EXPECT_EQ(h.width, 64);
    EXPECT_EQ(h.height, 48 + Heatmap::kLegendHeight);
    // the legend bar runs dark to bright
    const int bar_y = 48 + 6;
    EXPECT_LT(h.at(4, bar_y, 0) + h.at(4, bar_y, 1) + h.at(4, bar_y, 2),
              h.at(58, bar_y, 0) + h.at(58, bar_y, 1) + h.at(58, bar_y, 2));
    EXPECT_NE(r.out.find(std::string("wrote ") + png), std::string::npos) << r.out;
  }
  // the bounces map's legend reads 0 at the left: its glyph's top row lit at the text's origin
  const Image b = read_image(dir + "/w.bounces.png");
  EXPECT_GT(b.at(4, 48 + 16, 0), 0.9f);
}

TEST(TraceCli, EffectsOptionChangesTheImage) {
  const std::string dir = test::temp_dir("trace_effects");
  ASSERT_EQ(test::run_cli("render " + kSmall + " --spp 1 -q -o " + dir + "/all.exr").status, 0);
  ASSERT_EQ(test::run_cli("render " + kSmall + " --spp 1 -q -o " + dir + "/none.exr --effects none").status,
            0);
  const Image all = read_image(dir + "/all.exr"), none = read_image(dir + "/none.exr");
  EXPECT_NE(all.at(40, 24, 2), none.at(40, 24, 2));  // the glass sphere without its rays
  EXPECT_EQ(all.at(2, 2, 2), none.at(2, 2, 2));      // the sky the same
}

TEST(TraceCli, BadInputExitsTwoWithAClearMessage) {
  for (const char* pixel : {"abc", "-1,2", "64,0", "0,48", "1.5,2"}) {
    const auto r = test::run_cli("trace " + kSmall + " --pixel '" + pixel + "'");
    EXPECT_EQ(r.status, 2) << pixel << ": " << r.err;
    EXPECT_NE(r.err.find("--pixel"), std::string::npos) << pixel << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << pixel;
  }
  const auto sample = test::run_cli("trace " + kSmall + " --pixel 1,1 --sample 4");
  EXPECT_EQ(sample.status, 2);
  EXPECT_NE(sample.err.find("--sample"), std::string::npos) << sample.err;
  const auto effects = test::run_cli("trace " + kSmall + " --pixel 1,1 --effects shadow");
  EXPECT_EQ(effects.status, 2);
  EXPECT_NE(effects.err.find("--effects: unknown 'shadow'"), std::string::npos) << effects.err;
  const std::string dir = test::temp_dir("trace_bad");
  const auto heat = test::run_cli("render " + kSmall + " -o " + dir + "/w.exr --heatmap");
  EXPECT_EQ(heat.status, 2);
  EXPECT_NE(heat.err.find("--heatmap"), std::string::npos) << heat.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/w.exr"));
}

}  // namespace
}  // namespace rayvec
