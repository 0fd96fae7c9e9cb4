// `rayvec bench rays` runs at a tiny size (so the benchmark cannot rot), its JSON has the keys the
// issue specifies, packets agree with single rays, and bad usage exits 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/ray_tracer.h"
#include "platform/isa.h"
#include "test_support.h"

namespace rayvec {
namespace {

std::string write_octahedron(const std::string& dir) {
  const std::string path = dir + "/octa.obj";
  test::write_file(path,
                   "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                   "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
  return path;
}

// The number after `"key":` in the object that follows `"set":{` (empty when absent).
std::string field(const std::string& json, const std::string& set, const std::string& key) {
  const std::size_t open = json.find("\"" + set + "\":{");
  if (open == std::string::npos) return "";
  const std::size_t close = json.find('}', open);
  const std::size_t at = json.find("\"" + key + "\":", open);
  if (at == std::string::npos || at > close) return "";
  const std::size_t begin = at + key.size() + 3;
  return json.substr(begin, json.find_first_not_of("0123456789.", begin) - begin);
}

// The number right after `prefix` in `json`, and where it ends (npos when `prefix` is absent).
std::pair<double, std::size_t> number_after(const std::string& json, const std::string& prefix,
                                            std::size_t from = 0) {
  const std::size_t at = json.find(prefix, from);
  if (at == std::string::npos) return {0.0, std::string::npos};
  char* end = nullptr;
  const double value = std::strtod(json.c_str() + at + prefix.size(), &end);
  return {value, std::size_t(end - json.c_str())};
}

TEST(BenchRays, TinyRunPrintsJsonWithEverySetAndPacketsMatchSingleRays) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays"));
  const auto r = test::run_cli("bench rays " + obj + " --size 16x12 --repeats 1 --json --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* key : {"\"build_s\"", "\"bytes_per_tri\"", "\"isa\"", "\"threads\":2"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  for (const char* set : {"primary", "primary_packet", "shadow", "shadow_packet", "incoherent"})
    for (const char* key : {"rays", "hits", "checksum", "mrays_per_s"})
      EXPECT_NE(field(r.out, set, key), "") << set << "." << key << " in " << r.out;
  EXPECT_EQ(field(r.out, "primary", "rays"), "192");
  EXPECT_NE(field(r.out, "primary", "hits"), "0");
  EXPECT_EQ(field(r.out, "primary", "checksum"), field(r.out, "primary_packet", "checksum"));
  EXPECT_EQ(field(r.out, "shadow", "rays"), field(r.out, "primary", "hits"));
  // the same shadow rays by tiles: the checksum (a sum over pixels) does not depend on their order
  EXPECT_EQ(field(r.out, "shadow_packet", "rays"), field(r.out, "shadow", "rays"));
  EXPECT_EQ(field(r.out, "shadow_packet", "checksum"), field(r.out, "shadow", "checksum"));
}

// Every run names the vector FMA rate of each width this CPU has (0 for a width it lacks), so a
// host that runs 512-bit operations at half rate shows in the output that is quoted.
TEST(BenchRays, PrintsTheVectorFmaRatesOfTheHost) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_fma"));
  const auto j = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --builds 1 --json");
  ASSERT_EQ(j.status, 0) << j.err;
  const auto [avx2, after_avx2] = number_after(j.out, "\"fma_per_cycle\":{\"avx2\":");
  ASSERT_NE(after_avx2, std::string::npos) << j.out;
  // {"avx2":A,"avx512":B}: the second rate right after the first, the object closed after it
  ASSERT_EQ(j.out.compare(after_avx2, 10, ",\"avx512\":"), 0) << j.out;
  const auto [avx512, after_avx512] = number_after(j.out, ",\"avx512\":", after_avx2);
  ASSERT_EQ(j.out.compare(after_avx512, 1, "}"), 0) << j.out;
  for (const auto& [isa, rate] : {std::pair{Isa::avx2, avx2}, std::pair{Isa::avx512, avx512}}) {
    if (isa_supported(isa)) {
      // measured (an instrumented build runs the probe far below the hardware's rate), and within
      // what any x86-64 core can issue (no more than four FMA pipes)
      EXPECT_GT(rate, 0.0) << isa_name(isa);
      EXPECT_LT(rate, 8.0) << isa_name(isa);
    } else {
      EXPECT_EQ(rate, 0.0) << isa_name(isa);
    }
  }
  const auto t = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --builds 1");
  EXPECT_NE(t.out.find("vector FMAs per cycle: avx2 "), std::string::npos) << t.out;
}

// --builds N times N builds and reports their median as build_s (the upper median for even N).
TEST(BenchRays, BuildsReportsEveryBuildAndTheirMedian) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_builds"));
  const auto r = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --json --builds 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"builds\":4,"), std::string::npos) << r.out;
  const auto [median, after_median] = number_after(r.out, "\"build_s\":");
  ASSERT_NE(after_median, std::string::npos) << r.out;
  const std::string runs_key = ",\"build_runs_s\":[";
  ASSERT_EQ(r.out.compare(after_median, runs_key.size(), runs_key), 0) << r.out;
  const std::size_t list_begin = after_median + runs_key.size();
  const std::string list = r.out.substr(list_begin, r.out.find(']', list_begin) - list_begin);
  std::vector<double> runs;
  for (std::size_t at = 0; at < list.size();) {
    std::size_t used = 0;
    runs.push_back(std::stod(list.substr(at), &used));
    at += used + 1;
  }
  ASSERT_EQ(runs.size(), 4u) << list;
  std::sort(runs.begin(), runs.end());
  EXPECT_DOUBLE_EQ(median, runs[2]);
  EXPECT_EQ(test::run_cli("bench rays " + obj + " --size 4x4 --builds 0").status, 2);
}

// build_stages_s: the median wall time of each stage of the build (BvhBuildTimes), which within one
// build add up to no more than the whole; the text report lists them after the build's time.
TEST(BenchRays, BuildStagesAddUpToNoMoreThanTheBuild) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_stages"));
  const auto r = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --json --builds 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const double build = number_after(r.out, "\"build_s\":").first;
  double sum = 0;
  for (const char* stage : {"tree", "align", "collapse", "sort", "fill"}) {
    const auto [seconds, end] =
        number_after(r.out, std::string("\"") + stage + "\":", r.out.find("\"build_stages_s\":{"));
    ASSERT_NE(end, std::string::npos) << stage << ": " << r.out;
    EXPECT_GE(seconds, 0.0) << stage;
    sum += seconds;
  }
  EXPECT_GT(number_after(r.out, "\"tree\":").first, 0.0) << r.out;
  EXPECT_LE(sum, build) << r.out;
  const auto text = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --builds 1");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find(" s (ms: tree "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(", fill "), std::string::npos) << text.out;
}

// Off a terminal, every stage is one line on stderr; stdout keeps only the JSON object.
TEST(BenchRays, ProgressGoesToStderrOneLineAStage) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_progress"));
  const auto r = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --json --builds 2");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line : {"bench rays: loading ", "bench rays: building the BVH (1 of 2)\n",
                           "bench rays: building the BVH (2 of 2)\n", "bench rays: making the rays\n",
                           "bench rays: tracing primary rays\n", "bench rays: tracing primary packets\n",
                           "bench rays: tracing shadow rays\n", "bench rays: tracing incoherent rays\n"})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << " in " << r.err;
  ASSERT_FALSE(r.out.empty());
  EXPECT_EQ(r.out.front(), '{') << r.out;
  EXPECT_EQ(r.out.find("bench rays:"), std::string::npos) << r.out;
}

TEST(BenchRays, EveryIsaGivesTheSameChecksums) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_isa"));
  const auto ref = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --json --isa scalar");
  ASSERT_EQ(ref.status, 0) << ref.err;
  for (const char* isa : {"avx2", "avx512"}) {
    const auto r = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --json --isa " + isa);
    if (r.status != 0) continue;  // ISA not on this CPU (a usage error, tested elsewhere)
    for (const char* set : {"primary", "primary_packet", "shadow", "shadow_packet", "incoherent"})
      EXPECT_EQ(field(r.out, set, "checksum"), field(ref.out, set, "checksum")) << isa << " " << set;
  }
}

TEST(BenchRays, BadUsageExitsTwo) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_bad"));
  EXPECT_EQ(test::run_cli("bench rays " + obj + " --size 0x4").status, 2);
  EXPECT_EQ(test::run_cli("bench rays " + obj + " --size big").status, 2);
  EXPECT_EQ(test::run_cli("bench rays /nonexistent.obj --size 4x4").status, 2);
  EXPECT_EQ(test::run_cli("bench rays " + obj + " --bvh-width 5 --size 4x4").status, 2);
}

TEST(BenchRays, VsEmbreeRunsWhenBuiltWithEmbreeAndOtherwiseExitsTwo) {
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_embree"));
  const auto r = test::run_cli("bench rays " + obj + " --size 8x8 --repeats 1 --json --vs-embree");
  if (!embree_available()) {
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("without Embree"), std::string::npos) << r.err;
    return;
  }
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"embree\":{\"build_s\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"mismatches\":{\"primary\":0,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"shadow_packet\":0,"), std::string::npos) << r.out;
}

// The rival runs at rayvec's ISA (Embree's max_isa), so an AVX2 comparison is AVX2 against AVX2.
TEST(BenchRays, VsEmbreeCapsEmbreeAtRayvecsIsa) {
  if (!embree_available()) GTEST_SKIP() << "rayvec was built without Embree";
  const std::string obj = write_octahedron(test::temp_dir("bench_rays_embree_isa"));
  const std::string base = "bench rays " + obj + " --size 8x8 --repeats 1 --json --vs-embree --isa ";
  const auto scalar = test::run_cli(base + "scalar");
  ASSERT_EQ(scalar.status, 0) << scalar.err;
  EXPECT_NE(scalar.out.find("\"max_isa\":\"sse2\""), std::string::npos) << scalar.out;
  EXPECT_NE(scalar.out.find("\"mismatches\":{\"primary\":0,"), std::string::npos) << scalar.out;
  if (!isa_supported(Isa::avx2)) GTEST_SKIP() << "no AVX2 on this CPU: the avx2 half is skipped";
  const auto avx2 = test::run_cli(base + "avx2");
  ASSERT_EQ(avx2.status, 0) << avx2.err;
  EXPECT_NE(avx2.out.find("\"max_isa\":\"avx2\""), std::string::npos) << avx2.out;
}

}  // namespace
}  // namespace rayvec
