#include "bench/progress.h"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace rayvec {

StageLine::StageLine(std::string prefix) : prefix_(std::move(prefix)), tty_(isatty(2) != 0) {}

StageLine::~StageLine() { clear(); }

void StageLine::clear() const {
  if (tty_) std::fprintf(stderr, "\r\033[K");
}

void StageLine::show(const std::string& stage) const {
  std::fprintf(stderr, tty_ ? "\r\033[K%s: %s" : "%s: %s\n", prefix_.c_str(), stage.c_str());
}

}  // namespace rayvec
