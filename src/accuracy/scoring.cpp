#include "accuracy/scoring.h"

#include <cmath>
#include <cstdint>

namespace rayvec {

std::vector<ExactHit> oracle_closest(const HardCaseFamily& family) {
  const ExactOracle oracle(family.mesh);
  std::vector<ExactHit> out(family.rays.size());
  const auto n = static_cast<std::int64_t>(out.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t i = 0; i < n; ++i) out[i] = oracle.closest(family.rays[i]);
  return out;
}

FamilyScore score_family(std::span<const ExactHit> truth, std::span<const Hit> hits) {
  FamilyScore s;
  s.rays = truth.size();
  for (std::size_t i = 0; i < truth.size() && i < hits.size(); ++i) {
    const ExactHit& want = truth[i];
    const Hit& got = hits[i];
    if (std::isnan(got.t) || std::isnan(got.u) || std::isnan(got.v) || (!got.hit() && got.t != kInf))
      ++s.nan_outputs;
    if (want.hit()) ++s.oracle_hits;
    if (want.hit() && !got.hit()) {
      ++s.false_misses;
      if (s.false_miss_rays.size() < 8) s.false_miss_rays.push_back(i);
    } else if (!want.hit() && got.hit()) {
      ++s.false_hits;
    } else if (want.hit() && got.hit() && !want.is_nearest(got.tri)) {
      ++s.wrong_nearest;
    }
  }
  return s;
}

}  // namespace rayvec
