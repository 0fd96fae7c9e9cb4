// Packet experiment harness: times the bench's primary rays as 4×4-tile packets (as `rayvec bench
// rays` row primary_packet) through the tree's own packet traversal ("tree": librayvec.a's
// BvhKernels table; "stream": Bvh::closest_stream, as the bench calls it), through each variant
// compiled into this binary (packet_variant.cpp, built by packet_build.sh from the current
// sources or a copy of bvh_packet.inl) and through Embree's rtcIntersect16 ("embree"), interleaved
// round by round on the thread's CPU-time clock, one thread. Prints per variant the median, its
// ratio to "tree" and to Embree, and the range of the per-round ratios to Embree; checks every
// variant's hits (id and bit-identical t) against "tree".
// The packet functions overwrite the hits of their lanes (BvhKernels::closest_packet), so no reset
// is timed with them; variants named old* (a copy of an older bvh_packet.inl) get the older
// contract's caller work instead, as Bvh::closest_stream did it: hits reset, untraceable lanes out.
//   packet_bench MODEL.obj [ROUNDS]      RV_SIDE=N: N×N rays instead of 1024×1024
// RV_ISA=avx2: an AVX2 tree, Embree capped at AVX2, AVX2 variants of packet_variant.cpp (built by
// RV_ISA=avx2 packet_build.sh; each 4×4 tile as two 8-ray packets).
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "accel/bvh.h"
#include "bench/ray_sets.h"
#include "bench/ray_tracer.h"
#include "bvh/bvh_kernels.h"
#include "scene/obj_loader.h"

namespace rayvec::pbench {
using PacketFn = void (*)(const BvhArrays&, const TriangleArrays&, const TriangleKernels&, const Ray*,
                          Hit*, unsigned);
struct Entry {
  std::string name;
  PacketFn fn;
};
std::vector<Entry>& registry() {
  static std::vector<Entry> r;
  return r;
}
void register_variant(const char* name, PacketFn fn) { registry().push_back({name, fn}); }
}  // namespace rayvec::pbench

using namespace rayvec;

namespace {

double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: packet_bench MODEL.obj [ROUNDS]\n");
    return 2;
  }
  const ObjModel model = load_obj(argv[1]);
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;
  const bool avx2 = std::getenv("RV_ISA") && std::strcmp(std::getenv("RV_ISA"), "avx2") == 0;
  const TraceConfig config{avx2 ? Isa::avx2 : Isa::avx512, Intersector::mt};
  const TriangleKernels& kernels = triangle_kernels(config.isa, config.intersector);
  const Bvh bvh(model.mesh, config);
  const BvhKernels& table = bvh_kernels(config.isa, bvh.tree().width());
  double embree_build = 0;
  const std::unique_ptr<RayTracer> embree = make_embree_tracer(model.mesh, 1, avx2 ? "avx2" : "avx512", embree_build);
  const int side = std::getenv("RV_SIDE") ? std::atoi(std::getenv("RV_SIDE")) : 1024;
  const BenchCamera cam = frame_mesh(model.mesh, side, side);
  std::vector<uint32_t> start;
  const RaySet tiles = primary_tiles(cam, start);

  struct Run {
    std::string name;
    pbench::PacketFn fn;  // null: embree or (stream) Bvh::closest_stream
    std::vector<double> s;
    bool stream = false;
  };
  std::vector<Run> runs;
  // the tree's table traces 16-ray tiles only with 16-ray packets (AVX2: "stream" instead)
  runs.push_back({"tree", avx2 ? nullptr : table.closest_packet, {}, avx2});
  runs.push_back({"stream", nullptr, {}, true});
  for (const auto& e : pbench::registry()) runs.push_back({e.name, e.fn, {}});
  runs.push_back({"embree", nullptr, {}});
  std::vector<Hit> want(tiles.rays.size()), out(tiles.rays.size());
  auto trace = [&](const Run& r, std::vector<Hit>& hits) {
    const double t0 = cpu_now();
    for (std::size_t k = 0; k + 1 < start.size(); ++k) {
      const uint32_t s = start[k], n = start[k + 1] - s;
      if (r.stream) {
        bvh.closest_stream(tiles.rays.data() + s, hits.data() + s, n);
        continue;
      }
      if (!r.fn) {
        embree->closest_packet(tiles.rays.data() + s, hits.data() + s, n);
        continue;
      }
      unsigned lanes = (1u << n) - 1u;
      if (r.name.rfind("old", 0) == 0) {  // the contract before 1fc0de1: the caller resets and filters
        lanes = 0;
        for (uint32_t i = 0; i < n; ++i) {
          hits[s + i] = Hit{};
          const Ray& q = tiles.rays[s + i];
          const bool ok = std::isfinite(q.org.x) && std::isfinite(q.org.y) && std::isfinite(q.org.z) &&
                          std::isfinite(q.dir.x) && std::isfinite(q.dir.y) && std::isfinite(q.dir.z) &&
                          !std::isnan(q.tmin) && !std::isnan(q.tmax);
          lanes |= unsigned(ok) << i;
        }
        if (lanes == 0) continue;
      }
      r.fn(bvh.tree().arrays(), bvh.triangles().arrays(), kernels, tiles.rays.data() + s, hits.data() + s,
           lanes);
    }
    return cpu_now() - t0;
  };
  trace(runs[0], want);
  for (int round = 0; round <= rounds; ++round)
    for (Run& r : runs) {
      const double s = trace(r, out);
      if (round > 0) r.s.push_back(s);
      else {
        std::size_t bad = 0;
        for (std::size_t i = 0; i < out.size(); ++i)
          bad += out[i].tri != want[i].tri || ((r.fn || r.stream) && std::memcmp(&out[i].t, &want[i].t, 4) != 0);
        if (bad) std::printf("%s: %zu rays differ from tree\n", r.name.c_str(), bad);
      }
    }
  std::printf("%s: %zu triangles, %zu rays in %zu tiles, %d rounds (median thread CPU s, 1 thread)\n",
              argv[1], model.mesh.size(), tiles.rays.size(), start.size() - 1, rounds);
  std::printf("%-12s %9s %8s %8s %8s %15s\n", "variant", "median_s", "Mrays/s", "vs_tree", "vs_embree",
              "round_ratio_range");
  const double tree = median(runs[0].s), emb = median(runs.back().s);
  for (const Run& r : runs) {
    std::vector<double> q;
    for (int i = 0; i < rounds; ++i) q.push_back(runs.back().s[i] / r.s[i]);
    std::sort(q.begin(), q.end());
    const double m = median(r.s);
    std::printf("%-12s %9.5f %8.2f %8.3f %8.3f %7.3f-%-7.3f\n", r.name.c_str(), m,
                double(tiles.rays.size()) / m * 1e-6, tree / m, emb / m, q.front(), q.back());
  }
}
