// Progress: how a long benchmark says what it is doing (a stage name per call), so the command can
// show it on stderr — redrawn in place on a terminal, one line each otherwise.
#pragma once
#include <functional>
#include <string>

namespace rayvec {

// Called with the stage about to run; may be empty (no progress shown).
using Progress = std::function<void(const std::string&)>;

}  // namespace rayvec
