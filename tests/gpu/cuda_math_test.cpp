// The device math compiled for the host (gpu/host_reference.h runs the very loops and arithmetic the
// CUDA kernels run) against the CPU kernels, on the hard-case families, random scenes and the
// visibility workload. Contracts checked: with the scalar ISA's rounding (fused = false) the same
// ids, t, u and v bit for bit as the scalar kernel; with the device's rounding (fused = true) the
// same bits as the AVX2 and AVX-512 kernels (skipped where the CPU lacks them); any-hit answers equal;
// the two device layouts equal. No GPU needed: these run in every build.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "accel/visibility.h"
#include "accuracy/hard_cases.h"
#include "gpu/gpu_scene.h"
#include "gpu/host_reference.h"
#include "gpu/math_dispatch.h"
#include "gpu/visibility_segments.h"
#include "kernels/triangle_kernels.h"
#include "kernels/triangle_soa.h"

namespace rayvec {
namespace {

constexpr Intersector kDeviceIntersectors[] = {Intersector::mt, Intersector::mt64, Intersector::watertight,
                                               Intersector::watertight64};

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_hit(const Hit& a, const Hit& b) {
  return a.tri == b.tri && same_bits(a.t, b.t) && same_bits(a.u, b.u) && same_bits(a.v, b.v);
}

std::string describe(const Hit& h) {
  return "{tri " + std::to_string(h.tri) + ", t " + std::to_string(h.t) + ", u " + std::to_string(h.u) +
         ", v " + std::to_string(h.v) + "}";
}

struct Case {
  std::string name;
  TriangleMesh mesh;
  std::vector<Ray> rays;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (HardCaseFamily& f : hard_case_families(2024, 1))
    out.push_back({f.name, std::move(f.mesh), std::move(f.rays)});
  HardCaseFamily control = random_control_family(99, 1);
  out.push_back({"control", std::move(control.mesh), std::move(control.rays)});
  return out;
}

std::vector<Hit> cpu_closest(const TriangleSoA& soa, const std::vector<Ray>& rays, Isa isa, Intersector i) {
  const TriangleKernels& k = triangle_kernels(isa, i);
  std::vector<Hit> hits(rays.size());
  for (std::size_t r = 0; r < rays.size(); ++r) k.closest(soa.arrays(), 0, soa.size(), rays[r], hits[r]);
  return hits;
}

// Counts the rays whose hits differ between the device math and the CPU kernel of `isa`.
void expect_closest_equal(Isa isa, bool fused) {
  for (const Case& c : cases()) {
    const TriangleSoA soa(c.mesh);
    const gpu::GpuTriangles tris = gpu::make_gpu_triangles(c.mesh);
    for (Intersector i : kDeviceIntersectors) {
      const std::vector<Hit> want = cpu_closest(soa, c.rays, isa, i);
      const std::vector<Hit> got = gpu::host_closest(tris, c.rays, i, fused);
      int differ = 0;
      for (std::size_t r = 0; r < want.size(); ++r)
        if (!same_hit(want[r], got[r]) && differ++ < 3)
          ADD_FAILURE() << c.name << " " << intersector_name(i) << " ray " << r << ": cpu "
                        << describe(want[r]) << " device math " << describe(got[r]);
      EXPECT_EQ(differ, 0) << c.name << " " << intersector_name(i) << ": " << differ << " of " << want.size()
                           << " rays differ";
    }
  }
}

TEST(CudaMath, ClosestMatchesScalarKernelBitForBit) { expect_closest_equal(Isa::scalar, false); }

TEST(CudaMath, ClosestWithFusedRoundingMatchesSimdKernelsBitForBit) {
  int checked = 0;
  for (Isa isa : {Isa::avx2, Isa::avx512}) {
    if (!isa_supported(isa)) continue;
    expect_closest_equal(isa, true);
    ++checked;
  }
  if (checked == 0) GTEST_SKIP() << "this CPU has neither AVX2 nor AVX-512: no fused CPU kernel to compare";
}

TEST(CudaMath, OccludedMatchesCpuKernels) {
  for (const Case& c : cases()) {
    const TriangleSoA soa(c.mesh);
    const gpu::GpuTriangles tris = gpu::make_gpu_triangles(c.mesh);
    for (Intersector i : kDeviceIntersectors)
      for (Isa isa : supported_isas()) {
        const TriangleKernels& k = triangle_kernels(isa, i);
        const std::vector<uint8_t> got = gpu::host_occluded(tris, c.rays, nullptr, i, isa != Isa::scalar);
        int differ = 0;
        for (std::size_t r = 0; r < c.rays.size(); ++r)
          differ += got[r] != uint8_t(k.occluded(soa.arrays(), 0, soa.size(), c.rays[r], nullptr));
        EXPECT_EQ(differ, 0) << c.name << " " << intersector_name(i) << " vs " << isa_name(isa);
      }
  }
}

TEST(CudaMath, SoaLayoutMatchesAos) {
  for (const Case& c : cases()) {
    const gpu::GpuTriangles tris = gpu::make_gpu_triangles(c.mesh);
    for (Intersector i : kDeviceIntersectors) {
      const auto aos = gpu::host_closest(tris, c.rays, i, true, gpu::HostLayout::aos);
      const auto soa = gpu::host_closest(tris, c.rays, i, true, gpu::HostLayout::soa);
      for (std::size_t r = 0; r < aos.size(); ++r)
        ASSERT_TRUE(same_hit(aos[r], soa[r])) << c.name << " " << intersector_name(i) << " ray " << r;
    }
  }
}

// The visibility workload: a closed icosphere seen from outside and from inside, plus a vertex
// inside a second sphere; answers as compute_visibility's on the CPU brute force.
TEST(CudaMath, VisibilityMatchesCpu) {
  TriangleMesh mesh = make_icosphere({0, 0, 0}, 1.0, 3, 5);
  const TriangleMesh inner = make_icosphere({0.2, 0.1, 0.0}, 0.3, 2, 9);
  const auto base = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), inner.positions.begin(), inner.positions.end());
  for (auto t : inner.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  std::vector<Vec3f> verts = mesh.positions;
  verts.push_back({0.2f, 0.1f, 0.0f});  // inside the inner sphere
  verts.push_back({kInf, 0.0f, 0.0f});  // undefined
  for (Vec3f origin : {Vec3f{0.1f, -3.0f, 0.4f}, Vec3f{0.0f, 0.0f, 0.5f}}) {
    for (Intersector i : kDeviceIntersectors) {
      TraceConfig config;
      config.isa = Isa::scalar;
      config.intersector = i;
      const auto accel = make_accelerator(AccelKind::brute, mesh, config);
      const std::vector<Visibility> want = compute_visibility(*accel, mesh, verts, origin);
      const gpu::VisibilitySegments s = gpu::visibility_segments(verts, origin);
      const gpu::GpuTriangles tris = gpu::make_gpu_triangles(mesh);
      const auto occluded = gpu::host_occluded(tris, s.rays, s.points.data(), i, false);
      const std::vector<Visibility> got = gpu::visibility_answers(s, verts.size(), occluded);
      int visible = 0;
      for (Visibility v : got) visible += v == Visibility::visible;
      EXPECT_EQ(got, want) << intersector_name(i);
      EXPECT_GT(visible, 10);
      EXPECT_LT(visible, int(verts.size()) - 10);
    }
  }
}

TEST(CudaMath, PaperHasNoDeviceMath) {
  EXPECT_FALSE(gpu::device_supports(Intersector::paper));
  const gpu::GpuTriangles tris = gpu::make_gpu_triangles(make_octahedron({0, 0, 0}, 1.0, 0));
  const std::vector<Ray> rays{Ray{{0, 0, -3}, {0, 0, 1}}};
  EXPECT_THROW(gpu::host_closest(tris, rays, Intersector::paper, true), std::invalid_argument);
}

}  // namespace
}  // namespace rayvec
