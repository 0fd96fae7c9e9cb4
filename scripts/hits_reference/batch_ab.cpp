// batch_ab: the in-process A/B of docs/benchmarks.md#decision-batched-tracing — the same accelerator,
// one thread, rays one by one (accel.closest / accel.occluded, the former path of `rayvec hits`)
// against trace_closest / trace_occluded (the stream path), alternating runs on the thread CPU
// clock; checks that both give the same bits. Not part of rayvec; built against a Release build:
//   B=build; g++ -O2 -std=c++20 -fopenmp -Isrc scripts/hits_reference/batch_ab.cpp -o batch_ab \
//     $B/src/librayvec_{bench,scene,image,io,core}.a -ltinyobjloader
//   ./batch_ab MESH.obj RAYS.csv brute|bvh [closest|any] [RUNS]
#include <omp.h>

#include <cstdio>
#include <cstring>
#include <vector>
#include "accel/accelerator.h"
#include "bench/cpu_clock.h"
#include "io/rays_csv.h"
#include "scene/obj_loader.h"
using namespace rayvec;
int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: batch_ab MESH.obj RAYS.csv brute|bvh [closest|any] [RUNS]\n");
    return 2;
  }
  const ObjModel model = load_obj(argv[1]);
  const RayBatch rays = read_rays_csv(argv[2]);
  const AccelKind kind = std::strcmp(argv[3], "bvh") == 0 ? AccelKind::bvh : AccelKind::brute;
  const bool any = argc > 4 && std::strcmp(argv[4], "any") == 0;
  const int reps = argc > 5 ? atoi(argv[5]) : 3;
  omp_set_num_threads(1);
  auto accel = make_accelerator(kind, model.mesh, {best_isa(), Intersector::mt});
  std::vector<Hit> a(rays.size()), b(rays.size());
  std::vector<uint8_t> oa(rays.size()), ob(rays.size());
  double ta = 0, tb = 0;
  for (int r = 0; r < reps; ++r) {
    double s = thread_cpu_seconds();
    if (any)
      for (size_t i = 0; i < rays.size(); ++i) oa[i] = accel->occluded(rays[i]);
    else
      for (size_t i = 0; i < rays.size(); ++i) a[i] = accel->closest(rays[i]);
    double t1 = thread_cpu_seconds() - s;
    s = thread_cpu_seconds();
    if (any)
      trace_occluded(*accel, rays, ob);
    else
      trace_closest(*accel, rays, b);
    double t2 = thread_cpu_seconds() - s;
    ta += t1;
    tb += t2;
    std::printf("per-ray %.3f  stream %.3f  ratio %.2f\n", t1, t2, t1 / t2);
  }
  size_t diff = 0;
  for (size_t i = 0; i < rays.size(); ++i)
    diff += any ? oa[i] != ob[i] : (a[i].tri != b[i].tri || memcmp(&a[i], &b[i], sizeof(Hit)) != 0);
  std::printf("%s %s: per-ray %.3f stream %.3f (%.2fx), %zu differ, %.2f G tests/s stream\n", argv[3],
              any ? "any" : "closest", ta / reps, tb / reps, ta / tb, diff,
              double(rays.size()) * model.mesh.size() / (tb / reps) * 1e-9);
}
