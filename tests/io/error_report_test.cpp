// report_warnings: every warning up to kShownWarnings, then one line with how many more.
#include "io/error_report.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayvec {
namespace {

std::string printed(const std::vector<std::string>& warnings, const char* label = "warning") {
  testing::internal::CaptureStderr();
  report_warnings(warnings, label);
  return testing::internal::GetCapturedStderr();
}

TEST(ReportWarnings, PrintsTheFirstOnesAndCountsTheRest) {
  EXPECT_EQ(printed({}), "");
  EXPECT_EQ(printed({"a.obj: one", "a.obj: two"}, "error"), "error: a.obj: one\nerror: a.obj: two\n");
  std::vector<std::string> many;
  std::string want;
  for (std::size_t i = 0; i < kShownWarnings + 5; ++i) {
    many.push_back("m.obj: w" + std::to_string(i));
    if (i < kShownWarnings) want += "warning: m.obj: w" + std::to_string(i) + "\n";
  }
  want += "warning: 5 more not shown (" + std::to_string(kShownWarnings + 5) + " in all)\n";
  EXPECT_EQ(printed(many), want);
  many.resize(kShownWarnings);
  EXPECT_EQ(printed(many).find("more not shown"), std::string::npos);
}

}  // namespace
}  // namespace rayvec
