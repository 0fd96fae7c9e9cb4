// RenderStats::json must be the whole object whatever the numbers: it was once cut off at 255
// bytes (a fixed snprintf buffer) — invalid JSON in every --stats-json file.
#include "render/render_stats.h"

#include <gtest/gtest.h>

namespace rayvec {
namespace {

RenderStats big_stats() {
  RenderStats s;
  s.rays =
      RayCounts{18446744073709551ull, 12345678901234567ull, 98765432109876543ull, 1ull, 9223372036854775ull};
  s.load_seconds = 123456.789;
  s.build_seconds = 0.000123;
  s.render_seconds = 98765.4321;
  s.write_seconds = 1.5;
  s.primary_thread_seconds = 1e7;
  s.shading_thread_seconds = 2e7;
  s.threads = 128;
  return s;
}

TEST(RenderStats, JsonIsTheWholeObjectForLargeValues) {
  const std::string json = big_stats().json();
  ASSERT_GE(json.size(), 2u);
  EXPECT_EQ(json.substr(json.size() - 2), "}\n") << json;
  EXPECT_NE(json.find("\"threads\": 128"), std::string::npos) << json;
  EXPECT_NE(json.find("\"rays_per_second\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"shading_thread\": 20000000.000000"), std::string::npos) << json;
  EXPECT_NE(json.find("\"primary_hits\": 9223372036854775}"), std::string::npos) << json;
  EXPECT_EQ(json.find('\0'), std::string::npos);
}

TEST(RenderStats, TextKeepsEveryLine) {
  const std::string text = big_stats().text();
  EXPECT_NE(text.find("18446744073709551 primary"), std::string::npos) << text;
  EXPECT_NE(text.find("(128 threads)"), std::string::npos) << text;
  EXPECT_NE(text.find("camera rays that hit: 9223372036854775 of 18446744073709551 (50.0 %)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("shading + secondary rays 20000000.000 s"), std::string::npos) << text;
}

}  // namespace
}  // namespace rayvec
