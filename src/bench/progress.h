// Progress: how a long benchmark says what it is doing (a stage name per call), and StageLine, the
// commands' way of showing it on stderr — redrawn in place on a terminal, one line each otherwise,
// so stdout stays the table or the JSON.
#pragma once
#include <functional>
#include <string>

namespace rayvec {

// Called with the stage about to run; may be empty (no progress shown).
using Progress = std::function<void(const std::string&)>;

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
  bool tty_;
};

}  // namespace rayvec
