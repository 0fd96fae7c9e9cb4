// Progress on stderr, so that stdout keeps only the results (a table, JSON): StageLine says which
// stage a long command is in ("bench rays: tracing shadow rays"), ProgressBar how much of a render
// is done ("[#######.....]  58%"). Both write through TerminalLine: on a terminal one line, redrawn
// in place; elsewhere (a pipe, a log) a stage is a line of its own and a bar is not drawn at all.
#pragma once
#include <functional>
#include <string>

namespace rayvec {

// Called with the stage about to run; may be empty (no progress shown).
using Progress = std::function<void(const std::string&)>;

// The one line of stderr a progress display owns.
class TerminalLine {
 public:
  TerminalLine();  // looks once whether stderr is a terminal
  bool on_terminal() const { return tty_; }
  // On a terminal: replaces the line with `text`. Elsewhere: writes `text` as a line of its own.
  void show(const std::string& text) const;
  // On a terminal: empties the line (before results are printed). Elsewhere: nothing.
  void clear() const;
  // On a terminal: ends the line, keeping its text. Elsewhere: nothing.
  void finish() const;

 private:
  bool tty_;
};

// "PREFIX: stage" on stderr. On a terminal the line is redrawn in place, and cleared by clear() —
// call it before printing results — and when the StageLine ends (also when an error unwinds past
// it, so the error starts on a clean line).
class StageLine {
 public:
  explicit StageLine(std::string prefix);
  ~StageLine();
  StageLine(const StageLine&) = delete;
  StageLine& operator=(const StageLine&) = delete;
  void show(const std::string& stage) const;
  void clear() const;
  Progress progress() const {
    return [this](const std::string& stage) { show(stage); };
  }

 private:
  std::string prefix_;
  TerminalLine line_;
};

// "[#######.....]  58%" redrawn in place on stderr, only when wanted and stderr is a terminal, so
// logs and pipes stay clean. finish() ends the line (the bar kept) — call it before printing
// results — and so does the end of the ProgressBar if finish() was not called.
class ProgressBar {
 public:
  explicit ProgressBar(bool wanted);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  void update(double fraction);  // 0..1; redraws only when the shown percentage changes
  void finish();
  bool enabled() const { return enabled_; }
  // update() as a callback (render()'s progress); empty when not enabled.
  std::function<void(double)> progress() {
    if (!enabled_) return {};
    return [this](double fraction) { update(fraction); };
  }

 private:
  TerminalLine line_;
  bool enabled_;
  int shown_ = -1;
};

}  // namespace rayvec
