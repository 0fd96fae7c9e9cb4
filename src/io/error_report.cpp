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

}  // namespace rayvec
