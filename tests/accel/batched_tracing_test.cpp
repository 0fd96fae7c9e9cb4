// Batches of rays (trace_closest, trace_occluded, compute_visibility) go through the accelerators'
// stream paths, never ray by ray, and give bit for bit what the single-ray queries give: brute force
// (closest_batch / occluded_batch, across several triangle chunks) and BVH (packets), closest and
// any-hit with per-ray filters, every intersector, every ISA this CPU has (the others are skipped
// and named), with more threads than one.
#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "accel/brute_force.h"
#include "accel/bvh_accelerator.h"
#include "accel/visibility.h"
#include "bvh/bvh_scenes.h"
#include "kernels/closest_batch.h"

namespace rayvec {
namespace {

// Counts the rays each path sees; the stream calls delegate to a real brute force accelerator.
class SpyAccelerator final : public Accelerator {
 public:
  explicit SpyAccelerator(const TriangleMesh& mesh) : inner_(mesh, TraceConfig{}) {}
  Hit closest(const Ray& ray) const override {
    ++single;
    return inner_.closest(ray);
  }
  bool occluded(const Ray& ray, const HitFilter* filter) const override {
    ++single;
    return inner_.occluded(ray, filter);
  }
  void closest_stream(const Ray* rays, Hit* hits, std::size_t n) const override {
    streamed += n;
    if (n > largest_group) largest_group = n;
    inner_.closest_stream(rays, hits, n);
  }
  void occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                       const HitFilter* filters) const override {
    streamed += n;
    if (n > largest_group) largest_group = n;
    inner_.occluded_stream(rays, occluded, n, filters);
  }
  std::size_t bytes() const override { return inner_.bytes(); }
  const TraceConfig& config() const override { return inner_.config(); }

  mutable std::atomic<std::size_t> single{0}, streamed{0}, largest_group{0};

 private:
  BruteForce inner_;
};

RayBatch to_batch(const std::vector<Ray>& rays) {
  RayBatch batch;
  for (const Ray& r : rays) batch.push_back(r);
  return batch;
}

TEST(BatchedTracing, BatchesTakeTheStreamPathNeverSingleRays) {
  const TriangleMesh mesh = test::random_soup(500, 0.2f, 3);
  const std::vector<Ray> rays = test::random_rays(1003, 1.5f, 4);
  const RayBatch batch = to_batch(rays);
  const SpyAccelerator spy(mesh);
  omp_set_num_threads(2);
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occluded(rays.size());
  trace_closest(spy, rays, hits);
  trace_closest(spy, batch, hits);
  trace_occluded(spy, rays, occluded);
  trace_occluded(spy, batch, occluded);
  EXPECT_EQ(spy.single.load(), 0u);
  EXPECT_EQ(spy.streamed.load(), 4 * rays.size());
  EXPECT_LE(spy.largest_group.load(), spy.stream_rays());
  EXPECT_GT(spy.largest_group.load(), 1u);

  std::vector<Vec3f> verts(mesh.positions.begin(), mesh.positions.begin() + 200);
  verts[7] = {std::nanf(""), 0, 0};  // undefined: not traced at all
  spy.streamed = 0;
  compute_visibility(spy, mesh, verts, {0, 0, 3});
  EXPECT_EQ(spy.single.load(), 0u);
  EXPECT_EQ(spy.streamed.load(), verts.size() - 1);
}

struct BatchCase {
  Isa isa;
  Intersector intersector;
  AccelKind accel;
};

std::vector<BatchCase> batch_cases() {
  std::vector<BatchCase> cases;
  for (Isa isa : kAllIsas)
    for (Intersector i : kAllIntersectors)
      for (AccelKind a : {AccelKind::brute, AccelKind::bvh}) cases.push_back({isa, i, a});
  return cases;
}

class BatchedTracingIsa : public ::testing::TestWithParam<BatchCase> {
 protected:
  void SetUp() override {
    if (!isa_supported(GetParam().isa))
      GTEST_SKIP() << "CPU lacks " << isa_name(GetParam().isa) << ": skipped";
    omp_set_num_threads(2);
  }
};

bool same_bits(const Hit& a, const Hit& b) { return std::memcmp(&a, &b, sizeof(Hit)) == 0; }

// Ignores the triangles whose id ≡ the ray's index (mod 3): a different filter for every ray, so
// a filter applied to the wrong ray changes the answers.
struct RayIndex {
  int32_t index;
};
bool ignore_same_residue(const void* context, int32_t tri) {
  return tri % 3 == static_cast<const RayIndex*>(context)->index % 3;
}

TEST_P(BatchedTracingIsa, StreamsEqualSingleRayQueriesBitForBit) {
  const BatchCase c = GetParam();
  // More than two brute force triangle chunks, so rays cross chunk boundaries (and any-hit rays
  // leave the batch in different chunks); duplicates test the lowest-id tie rule.
  const TriangleMesh mesh = test::random_soup(int(2 * kTriangleChunk + 1000), 0.15f, 11);
  std::vector<Ray> rays = test::random_rays(1000 + 7, 1.5f, 12);
  rays[5].org.x = std::numeric_limits<float>::quiet_NaN();  // never hits, on every path
  rays[6].dir = {kInf, 0, 0};
  // A pinhole camera in scan order: coherent groups, which a BVH traces as packets.
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 40; ++x)
      rays.push_back(Ray{{0.1f, -0.05f, 2.5f}, {float(x - 20) / 40.0f, float(y - 12) / 40.0f, -1.0f}});
  const auto accel = make_accelerator(c.accel, mesh, TraceConfig{c.isa, c.intersector});

  std::vector<Hit> span_hits(rays.size()), batch_hits(rays.size());
  trace_closest(*accel, rays, span_hits);
  trace_closest(*accel, to_batch(rays), batch_hits);
  std::size_t hit_count = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit single = accel->closest(rays[i]);
    hit_count += single.hit();
    ASSERT_TRUE(same_bits(span_hits[i], single))
        << "ray " << i << ": tri " << span_hits[i].tri << " vs " << single.tri;
    ASSERT_TRUE(same_bits(batch_hits[i], single)) << "ray " << i;
  }
  EXPECT_GT(hit_count, rays.size() / 4);

  std::vector<RayIndex> index(rays.size());
  std::vector<HitFilter> filters(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    index[i] = {int32_t(i)};
    filters[i] = {&ignore_same_residue, &index[i]};
  }
  std::vector<uint8_t> plain(rays.size()), filtered(rays.size()), from_batch(rays.size());
  trace_occluded(*accel, rays, plain);
  trace_occluded(*accel, rays, filtered, filters.data());
  trace_occluded(*accel, to_batch(rays), from_batch);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_EQ(plain[i], accel->occluded(rays[i]) ? 1 : 0) << "ray " << i;
    ASSERT_EQ(from_batch[i], plain[i]) << "ray " << i;
    ASSERT_EQ(filtered[i], accel->occluded(rays[i], &filters[i]) ? 1 : 0) << "ray " << i;
    differ += filtered[i] != plain[i];
  }
  EXPECT_GT(differ, 0u);  // the filters matter
}

TEST(BatchedTracing, PacketsOnlyForRaysFromOneOriginInANarrowCone) {
  std::vector<Ray> row;
  for (int x = 0; x < 16; ++x) row.push_back(Ray{{0, 0, 3}, {float(x) / 200.0f, 0.1f, -1.0f}});
  EXPECT_TRUE(packet_coherent(row.data(), row.size()));
  EXPECT_TRUE(packet_coherent(row.data(), 1));
  std::vector<Ray> moved = row;
  moved[9].org.x = 1e-3f;  // another origin
  EXPECT_FALSE(packet_coherent(moved.data(), moved.size()));
  std::vector<Ray> wide = row;
  wide[15].dir = {1.0f, 0.1f, -1.0f};  // 45 degrees off
  EXPECT_FALSE(packet_coherent(wide.data(), wide.size()));
  std::vector<Ray> nan = row;
  nan[3].dir.y = std::nanf("");
  EXPECT_FALSE(packet_coherent(nan.data(), nan.size()));
  const std::vector<Ray> random = test::random_rays(16, 1.5f, 5);
  EXPECT_FALSE(packet_coherent(random.data(), random.size()));
}

std::string batch_case_name(const ::testing::TestParamInfo<BatchCase>& info) {
  return std::string(isa_name(info.param.isa)) + "_" + intersector_name(info.param.intersector) + "_" +
         accel_name(info.param.accel);
}

INSTANTIATE_TEST_SUITE_P(AllIsas, BatchedTracingIsa, ::testing::ValuesIn(batch_cases()), batch_case_name);

}  // namespace
}  // namespace rayvec
