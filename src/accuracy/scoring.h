// Scoring an intersector's closest hits against the exact oracle, per hard-case family.
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "accuracy/exact_oracle.h"
#include "accuracy/hard_cases.h"

namespace rayvec {

struct FamilyScore {
  std::size_t rays = 0;
  std::size_t oracle_hits = 0;               // rays the oracle says hit something
  std::size_t false_misses = 0;              // oracle: hit; intersector: miss
  std::size_t false_hits = 0;                // oracle: miss; intersector: hit
  std::size_t wrong_nearest = 0;             // both hit, but not a triangle at the exact nearest t
  std::size_t nan_outputs = 0;               // a NaN in t, u or v, or a miss whose t is not +inf
  std::vector<std::size_t> false_miss_rays;  // indices of the first few false misses
};

// The exact nearest hit of every ray of the family (OpenMP-parallel; slow, exact).
std::vector<ExactHit> oracle_closest(const HardCaseFamily& family);

// Compares hits[i] with truth[i] for every ray.
FamilyScore score_family(std::span<const ExactHit> truth, std::span<const Hit> hits);

}  // namespace rayvec
