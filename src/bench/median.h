// median(): how every timing of the benchmarks and the accuracy report is reduced over its runs.
#pragma once
#include <algorithm>
#include <vector>

namespace rayvec {

// The median of v: the upper one of the two middle values for an even count; 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace rayvec
