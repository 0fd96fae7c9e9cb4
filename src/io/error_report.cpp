#include "io/error_report.h"

#include <cstdio>

namespace rayvec {
namespace {

std::string& last() {
  static std::string message;
  return message;
}

}  // namespace

void report_error(const std::string& message) {
  last() = message;
  std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
}

const std::string& last_error_message() { return last(); }

void report_warnings(const std::vector<std::string>& warnings, const char* label) {
  for (std::size_t i = 0; i < warnings.size() && i < kShownWarnings; ++i)
    std::fprintf(stderr, "%s: %s\n", label, warnings[i].c_str());
  if (warnings.size() > kShownWarnings)
    std::fprintf(stderr, "%s: %zu more not shown (%zu in all)\n", label, warnings.size() - kShownWarnings,
                 warnings.size());
}

}  // namespace rayvec
