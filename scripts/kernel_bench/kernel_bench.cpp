// Kernel experiment harness: thread CPU time (robust to other processes on this shared VM) and a
// calibrated dependent-add loop for the clock, so tests/cycle is measured in the same units.
//   kernel_bench TRIS SIDE INTERSECTOR BATCH      the product kernel (RV_VARIANT=1: the variant)
//   RV_AB=1 kernel_bench TRIS SIDE mt BATCH       product and variant alternately in one process,
//                                                 REPS pairs (RV_REPS, default 7): medians and the
//                                                 median of the paired ratios variant / product
// SIDE: a side x side subset spread over the 200 x 200 camera rays (200 = exactly the rays of
// `rayvec bench paper --models mod2`). BATCH 0 = one closest call per ray, else closest_batch of
// BATCH rays (64 = what `bench paper` and BruteForce::closest_stream run). RV_CHUNK=N: triangles per
// chunk of closest_batch (default: the library's kTriangleChunk); with RV_AB, the variant kernel is the
// product kernel at chunk N (so RV_AB=1 RV_CHUNK=N compares chunk sizes paired).
#include <time.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "bench/paper_scene.h"
#include "kernels/kernel_table.h"
#include "kernels/triangle_soa.h"
#include "kernels/closest_batch.h"
namespace rayvec { const TriangleKernels& variant_kernels(); }
using namespace rayvec;
static double cpu_now(){ timespec t; clock_gettime(CLOCK_THREAD_CPUTIME_ID,&t); return t.tv_sec+t.tv_nsec*1e-9; }
static double ghz(){ long n=100000000, x=0, i=n; double a=cpu_now();
  __asm__ volatile("1:\n .rept 16\n add $1, %0\n .endr\n dec %1\n jnz 1b\n":"+r"(x),"+r"(i));
  return n*16.0/(cpu_now()-a)/1e9; }
static double median(std::vector<double> v){ std::sort(v.begin(),v.end()); return v[v.size()/2]; }
int main(int argc,char**argv){
  int tris = argc>1?atoi(argv[1]):50000; int side = argc>2?atoi(argv[2]):60; const char* in = argc>3?argv[3]:"mt";
  Intersector I = *parse_intersector(in); int batch = argc>4?atoi(argv[4]):0;
  const int reps = getenv("RV_REPS") ? atoi(getenv("RV_REPS")) : 7;
  const bool ab = getenv("RV_AB") != nullptr;
  auto mesh = paper_triangles(tris); TriangleSoA soa(mesh); auto rays = paper_camera_rays(200);
  const TriangleKernels* ks[2] = {&triangle_kernels(Isa::avx512, I), &variant_kernels()};
  if (!ab && getenv("RV_VARIANT")) ks[0] = ks[1];
  std::vector<Ray> rs; for(int j=0;j<side;j++) for(int i=0;i<side;i++) rs.push_back(rays[(j*200/side)*200 + i*200/side]);
  const uint32_t chunk = getenv("RV_CHUNK") ? uint32_t(atoi(getenv("RV_CHUNK"))) : kTriangleChunk;
  if (ab && getenv("RV_CHUNK")) ks[1] = ks[0];
  // closest_batch with a chunk size of choice (the same loop as src/kernels/closest_batch.cpp)
  auto batch_at = [&](const TriangleKernels& k, uint32_t chunk_size, const Ray* r, Hit* h, std::size_t n) {
    for (uint32_t c = 0; c < soa.size();) {
      const uint32_t ce = soa.size() - c > chunk_size ? c + chunk_size : soa.size();
      std::size_t j = 0;
      if (k.closest_pair) for (; j + 2 <= n; j += 2) k.closest_pair(soa.arrays(), c, ce, r + j, h + j);
      for (; j < n; ++j) k.closest(soa.arrays(), c, ce, r[j], h[j]);
      c = ce;
    } };
  long long sum[2] = {0, 0};
  auto run = [&](const TriangleKernels& k, long long& chk, uint32_t chunk_size) {  // G tests/s of one pass
    double a=cpu_now();
    if (batch) { std::vector<Hit> hs(rs.size()); for(size_t b=0;b<rs.size();b+=batch){ size_t n=std::min<size_t>(batch, rs.size()-b); batch_at(k, chunk_size, rs.data()+b,hs.data()+b,n);} for(auto&h:hs) chk+=h.tri; }
    else for(auto& r: rs){ Hit h; k.closest(soa.arrays(),0,soa.size(),r,h); chk+=h.tri; }
    return double(rs.size())*tris/(cpu_now()-a)/1e9; };
  std::vector<double> rate[2], ratio, clk;
  for(int rep=0;rep<reps;rep++){ clk.push_back(ghz());
    if (!ab) { rate[0].push_back(run(*ks[0], sum[0], chunk)); continue; }
    double r[2]; const int first = rep & 1;  // alternate which kernel goes first
    const uint32_t chunks[2] = {kTriangleChunk, chunk};
    r[first] = run(*ks[first], sum[first], chunks[first]); r[1-first] = run(*ks[1-first], sum[1-first], chunks[1-first]);
    rate[0].push_back(r[0]); rate[1].push_back(r[1]); ratio.push_back(r[1]/r[0]); }
  const double c = median(clk);
  auto line = [&](const char* name, const std::vector<double>& v, long long chk) {
    const double g = median(v);
    printf("%s batch %d %s %d tris %zu rays: %.3f Gtests/s (cpu time, median of %d; min %.3f max %.3f), clock %.2f GHz -> %.3f tests/cycle [chk %lld]\n",
           name, batch, in, tris, rs.size(), g, reps, *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end()), c, g/c, chk / reps); };
  line(ab ? "product" : (getenv("RV_VARIANT") ? "variant" : "product"), rate[0], sum[0]);
  if (ab) { line("variant", rate[1], sum[1]);
    printf("variant / product: median of %d paired ratios %.3f (min %.3f max %.3f)%s\n", reps, median(ratio),
           *std::min_element(ratio.begin(), ratio.end()), *std::max_element(ratio.begin(), ratio.end()),
           sum[0] == sum[1] ? "" : "  CHECKSUMS DIFFER"); }
}
