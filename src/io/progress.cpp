#include "io/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace rayvec {

TerminalLine::TerminalLine() : tty_(::isatty(STDERR_FILENO) != 0) {}

void TerminalLine::show(const std::string& text) const {
  std::fprintf(stderr, tty_ ? "\r\033[K%s" : "%s\n", text.c_str());
  std::fflush(stderr);
}

void TerminalLine::clear() const {
  if (tty_) std::fputs("\r\033[K", stderr);
}

void TerminalLine::finish() const {
  if (tty_) std::fputs("\n", stderr);
}

StageLine::StageLine(std::string prefix) : prefix_(std::move(prefix)) {}

StageLine::~StageLine() { clear(); }

void StageLine::show(const std::string& stage) const { line_.show(prefix_ + ": " + stage); }

void StageLine::clear() const { line_.clear(); }

ProgressBar::ProgressBar(bool wanted) : enabled_(wanted && line_.on_terminal()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::finish() {
  if (enabled_ && shown_ >= 0) line_.finish();
  shown_ = -1;
}

void ProgressBar::update(double fraction) {
  if (!enabled_) return;
  const int percent = std::clamp(static_cast<int>(fraction * 100.0), 0, 100);
  if (percent == shown_) return;
  shown_ = percent;
  constexpr int kWidth = 40;
  std::string bar(kWidth, '.');
  std::fill_n(bar.begin(), percent * kWidth / 100, '#');
  char percent_text[16];
  std::snprintf(percent_text, sizeof percent_text, "%3d%%", percent);
  line_.show("[" + bar + "] " + percent_text);
}

}  // namespace rayvec
