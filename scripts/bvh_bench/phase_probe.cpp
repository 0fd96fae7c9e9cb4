// Phase probe (docs/benchmarks.md, "What slows in a slow phase"): rayvec's 4k primary single rays
// interleaved, round by round (~10 ms each), with resource probes — zmm FMA throughput, L2- and
// L3-sized pointer chases, a branchy loop — all on the thread CPU-time clock, to see which resource
// slows together with rayvec in the VM's slow phases. Not part of the product build (AVX-512 only):
//   g++ -std=c++20 -O2 -mavx512f -mfma -Isrc scripts/bvh_bench/phase_probe.cpp build/librayvec.a \
//       -ltinyobjloader -lOpenImageIO -lOpenImageIO_Util -lembree3 -lgmpxx -lgmp -fopenmp -o phase_probe
//   ./phase_probe sphere4k.obj 400 > probe.txt
#include <time.h>
#include <immintrin.h>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <random>
#include <algorithm>
#include "accel/bvh.h"
#include "bench/ray_sets.h"
#include "scene/obj_loader.h"
using namespace rayvec;
static double now() { timespec t; clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
__attribute__((noinline)) double fma_probe() {  // 8 independent zmm FMA chains, 2M iterations
  __m512 a[8]; for (int i = 0; i < 8; ++i) a[i] = _mm512_set1_ps(1.0f + i * 1e-3f);
  const __m512 m = _mm512_set1_ps(0.999999f), c = _mm512_set1_ps(1e-7f);
  double t0 = now();
  for (int k = 0; k < 200000; ++k) for (int i = 0; i < 8; ++i) a[i] = _mm512_fmadd_ps(a[i], m, c);
  double t = now() - t0; float s = 0; for (int i = 0; i < 8; ++i) s += _mm512_reduce_add_ps(a[i]);
  if (s == 12345) std::puts("x"); return t;
}
__attribute__((noinline)) double chase(const std::vector<uint32_t>& next, int steps) {
  uint32_t p = 0; double t0 = now();
  for (int i = 0; i < steps; ++i) p = next[p];
  double t = now() - t0; if (p == 0xffffffff) std::puts("x"); return t;
}
std::vector<uint32_t> cycle(size_t n, unsigned seed) {
  std::vector<uint32_t> perm(n); for (size_t i = 0; i < n; ++i) perm[i] = uint32_t(i);
  std::shuffle(perm.begin() + 1, perm.end(), std::mt19937(seed));
  std::vector<uint32_t> next(n); for (size_t i = 0; i < n; ++i) next[perm[i]] = perm[(i + 1) % n];
  // spread: use one entry per 64-byte line
  return next;
}
__attribute__((noinline)) double branchy(const std::vector<uint8_t>& bits) {
  double t0 = now(); unsigned s = 0;
  for (int r = 0; r < 4; ++r) for (uint8_t b : bits) { if (b) s += 3; else s ^= 5; }
  double t = now() - t0; if (s == 1) std::puts("x"); return t;
}
int main(int argc, char** argv) {
  const ObjModel model = load_obj(argv[1]);
  const Bvh bvh(model.mesh, TraceConfig{Isa::avx512, Intersector::mt});
  const BenchCamera cam = frame_mesh(model.mesh, 256, 256);
  const RaySet rays = primary_rays(cam);
  // pointer chases with one entry per cache line: L2-sized (256 KB) and L3-sized (8 MB)
  auto make = [](size_t bytes, unsigned seed) { size_t n = bytes / 64; auto c = cycle(n, seed);
    std::vector<uint32_t> v(n * 16); for (size_t i = 0; i < n; ++i) v[i * 16] = c[i] * 16; return v; };
  auto l2 = make(256 << 10, 1), l3 = make(8 << 20, 2);
  std::vector<uint8_t> bits(1 << 16); std::mt19937 g(3); for (auto& b : bits) b = g() & 1;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 200;
  std::printf("round rayvec_ms fma_ms l2chase_ms l3chase_ms branch_ms\n");
  for (int r = 0; r < rounds; ++r) {
    double t0 = now(); Hit sink{}; for (const Ray& ray : rays.rays) { Hit h = bvh.closest(ray); sink.tri ^= h.tri; }
    double tr = now() - t0;
    double tf = fma_probe(), t2 = chase(l2, 200000), t3 = chase(l3, 100000), tb = branchy(bits);
    std::printf("%d %.2f %.2f %.2f %.2f %.2f %d\n", r, tr * 1e3, tf * 1e3, t2 * 1e3, t3 * 1e3, tb * 1e3, sink.tri & 1);
  }
}
