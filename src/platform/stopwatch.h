// seconds_since(): wall-clock seconds on the steady clock since `t0`, the one way rayvec's commands
// and the renderer time their stages.
#pragma once
#include <chrono>

namespace rayvec {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace rayvec
