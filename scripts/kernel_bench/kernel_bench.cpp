// Kernel experiment harness: thread CPU time (robust to other processes on this shared VM) and a
// calibrated dependent-add loop for the clock, so tests/cycle is measured in the same units.
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
int main(int argc,char**argv){
  int tris = argc>1?atoi(argv[1]):50000; int side = argc>2?atoi(argv[2]):60; const char* in = argc>3?argv[3]:"mt";
  Intersector I = *parse_intersector(in); int batch = argc>4?atoi(argv[4]):0;
  auto mesh = paper_triangles(tris); TriangleSoA soa(mesh); auto rays = paper_camera_rays(200);
  const auto& k = getenv("RV_VARIANT") ? variant_kernels() : triangle_kernels(Isa::avx512, I);
  // rays: a side x side subset spread over the image
  std::vector<Ray> rs; for(int j=0;j<side;j++) for(int i=0;i<side;i++) rs.push_back(rays[(j*200/side)*200 + i*200/side]);
  std::vector<double> rate, clk; long long sum=0;
  for(int rep=0;rep<7;rep++){ clk.push_back(ghz()); double a=cpu_now();
    if (batch) { std::vector<Hit> hs(rs.size()); for(size_t b=0;b<rs.size();b+=batch){ size_t n=std::min<size_t>(batch, rs.size()-b); closest_batch(k, soa.arrays(),0,soa.size(),rs.data()+b,hs.data()+b,n);} for(auto&h:hs) sum+=h.tri; }
    else for(auto& r: rs){ Hit h; k.closest(soa.arrays(),0,soa.size(),r,h); sum+=h.tri; }
    double s=cpu_now()-a; rate.push_back(double(rs.size())*tris/s/1e9); }
  std::sort(rate.begin(),rate.end()); std::sort(clk.begin(),clk.end());
  double g=rate[3], c=clk[3];
  printf("batch %d %s %d tris %zu rays: %.3f Gtests/s (cpu time, median of 7), clock %.2f GHz -> %.3f tests/cycle [chk %lld]\n", batch, in, tris, rs.size(), g, c, g/c, sum);
}
