// ProgressBar: "[#######·····]  58%" redrawn in place on stderr — only when stderr is a terminal,
// so logs and pipes stay clean.
#pragma once
#include <cstdio>

namespace rayvec {

class ProgressBar {
 public:
  // Enabled when `wanted` and stderr is a terminal.
  explicit ProgressBar(bool wanted);
  ~ProgressBar();
  void update(double fraction);  // 0..1; redraws only when the shown percentage changes
  bool enabled() const { return enabled_; }

 private:
  bool enabled_;
  int shown_ = -1;
};

}  // namespace rayvec
