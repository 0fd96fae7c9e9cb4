// The hard-case families (src/accuracy/hard_cases.h) against the exact oracle, for every
// intersector × ISA × accelerator. Watertight modes must have zero false misses on the families
// whose rays cross a closed surface; every mode must keep NaN out of its outputs and never hit a
// degenerate triangle or a non-finite ray. The other rates are measured (`rayvec accuracy`), not
// asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "accuracy/hard_cases.h"
#include "accuracy/scoring.h"

namespace rayvec {
namespace {

struct Fixture {
  HardCaseFamily family;
  std::vector<ExactHit> truth;
};

const std::vector<Fixture>& fixtures() {
  static const std::vector<Fixture> all = [] {
    std::vector<Fixture> out;
    std::vector<HardCaseFamily> families = hard_case_families(2026, 1);
    families.push_back(random_control_family(2026, 1));
    for (HardCaseFamily& f : families) {
      std::vector<ExactHit> truth = oracle_closest(f);
      out.push_back({std::move(f), std::move(truth)});
    }
    return out;
  }();
  return all;
}

bool watertight(Intersector in) { return in == Intersector::watertight || in == Intersector::watertight64; }

bool finite_ray(const Ray& r) {
  return std::isfinite(r.org.x) && std::isfinite(r.org.y) && std::isfinite(r.org.z) &&
         std::isfinite(r.dir.x) && std::isfinite(r.dir.y) && std::isfinite(r.dir.z) && !std::isnan(r.tmin) &&
         !std::isnan(r.tmax);
}

// nullptr when the accelerator is not available yet (the BVH is built by another issue).
std::unique_ptr<Accelerator> try_make(AccelKind kind, const TriangleMesh& mesh, const TraceConfig& cfg) {
  try {
    return make_accelerator(kind, mesh, cfg);
  } catch (const std::exception&) {
    return nullptr;
  }
}

std::vector<Hit> trace(const Accelerator& accel, const std::vector<Ray>& rays) {
  RayBatch batch;
  for (const Ray& r : rays) batch.push_back(r);
  std::vector<Hit> hits(rays.size());
  trace_closest(accel, batch, hits);
  return hits;
}

struct Param {
  Isa isa;
  Intersector intersector;
  AccelKind accel;
};

class HardCases : public ::testing::TestWithParam<Param> {};

TEST_P(HardCases, MatchOracleWithinContract) {
  const Param p = GetParam();
  if (!isa_supported(p.isa)) GTEST_SKIP() << "CPU lacks " << isa_name(p.isa) << ": skipped";
  const TraceConfig cfg{p.isa, p.intersector};
  for (const Fixture& fx : fixtures()) {
    const HardCaseFamily& f = fx.family;
    const auto accel = try_make(p.accel, f.mesh, cfg);
    if (!accel) GTEST_SKIP() << "accelerator " << accel_name(p.accel) << " not available yet";
    const std::vector<Hit> hits = trace(*accel, f.rays);
    const FamilyScore s = score_family(fx.truth, hits);
    SCOPED_TRACE(f.name);
    EXPECT_EQ(s.nan_outputs, 0u);
    if (f.degenerate) {
      EXPECT_EQ(s.false_hits, 0u) << "a zero-area triangle was hit";
    }
    for (std::size_t i = 0; i < f.rays.size(); ++i) {
      const Ray& r = f.rays[i];
      if (!finite_ray(r)) {
        ASSERT_EQ(hits[i].tri, -1) << "non-finite ray " << i << " hit";
      }
    }
    if (f.crossing && watertight(p.intersector)) {
      EXPECT_GT(s.oracle_hits, f.rays.size() * 9 / 10) << "family should be made of crossing rays";
      EXPECT_EQ(s.false_misses, 0u) << "watertight mode let " << s.false_misses << " of " << s.oracle_hits
                                    << " rays slip through; first ray index "
                                    << (s.false_miss_rays.empty() ? 0 : s.false_miss_rays[0]);
    }
    RecordProperty(f.name, std::to_string(s.false_misses) + " false misses, " + std::to_string(s.false_hits) +
                               " false hits, " + std::to_string(s.wrong_nearest) + " wrong nearest of " +
                               std::to_string(s.rays));
  }
}

std::vector<Param> all_params() {
  std::vector<Param> out;
  for (AccelKind a : {AccelKind::brute, AccelKind::bvh})
    for (Isa isa : kAllIsas)
      for (Intersector in : kAllIntersectors) out.push_back({isa, in, a});
  return out;
}

INSTANTIATE_TEST_SUITE_P(AllModes, HardCases, ::testing::ValuesIn(all_params()), [](const auto& info) {
  return std::string(accel_name(info.param.accel)) + "_" + isa_name(info.param.isa) + "_" +
         intersector_name(info.param.intersector);
});

// The oracle itself on the families: crossing families really are made of rays that hit.
TEST(HardCaseFamilies, CrossingFamiliesHitAndDegenerateNeverHits) {
  for (const Fixture& fx : fixtures()) {
    std::size_t hits = 0;
    for (const ExactHit& h : fx.truth) hits += h.hit();
    if (fx.family.crossing) {
      EXPECT_EQ(hits, fx.truth.size()) << fx.family.name;
    }
    if (fx.family.degenerate) {
      EXPECT_EQ(hits, 0u) << fx.family.name;
    }
  }
}

// Same ids whatever the thread count (every mode), and whatever the ISA (watertight modes are
// FMA-free, so bit-identical; the others are only counted — FMA changes their rounding).
TEST(HardCaseFamilies, DeterministicAcrossThreadsAndIsas) {
  for (Intersector in : kAllIntersectors)
    for (const Fixture& fx : fixtures()) {
      const auto scalar = make_accelerator(AccelKind::brute, fx.family.mesh, {Isa::scalar, in});
      const std::vector<Hit> ref = trace(*scalar, fx.family.rays);
      for (Isa isa : supported_isas()) {
        const auto accel = make_accelerator(AccelKind::brute, fx.family.mesh, {isa, in});
        const std::vector<Hit> many = trace(*accel, fx.family.rays);  // all threads
        std::size_t isa_diffs = 0;
        for (std::size_t i = 0; i < many.size(); ++i) {
          if (isa == best_isa()) {  // one thread, in order
            ASSERT_EQ(accel->closest(fx.family.rays[i]).tri, many[i].tri) << fx.family.name << " ray " << i;
          }
          isa_diffs += many[i].tri != ref[i].tri;
        }
        if (watertight(in)) {
          EXPECT_EQ(isa_diffs, 0u) << fx.family.name << " " << isa_name(isa);
        }
      }
    }
}

}  // namespace
}  // namespace rayvec
