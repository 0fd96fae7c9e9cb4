// BVH experiment harness (docs/benchmarks.md, "BVH quality and parallel build"): builds several BVH
// variants of one mesh in one process and times the bench's primary, incoherent and shadow single rays
// through each, interleaved round by round on the thread's CPU-time clock, so that the load of other
// processes hits every variant alike; prints the median per variant and its ratio to the first.
// It also counts, per ray, wide nodes visited and 16-triangle leaf blocks tested — a load-free
// measure of tree quality.
//   bvh_bench MODEL.obj [ROUNDS] VARIANT...
//   VARIANT = name:key=value,key=value  (keys: block, max_leaf, trav, bins, width, trv=0|1,
//             isa=2 for AVX2 instead of AVX-512)
// trv=1 traverses with the variant traversal compiled into this harness (variant_avx512.cpp; with
// isa=2 its AVX2 copy), for
// the closest-hit sets and the shadow rays.
//   bvh_bench MODEL.obj phases [ROUNDS]   build phases (binary SAH, collapse, TriangleSoA fill) at
//                                         OMP_NUM_THREADS threads: wall and process CPU seconds
// RV_SIDE=N traces N×N primary rays instead of 1024×1024; RV_ROUNDS=1 prints every round's times.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <omp.h>

#include <chrono>

#include "accel/bvh.h"
#include "bvh/binned_sah_builder.h"
#include "bvh/wide_bvh.h"
#include "kernels/triangle_soa.h"
#include "bench/ray_sets.h"
#include "bvh/bvh_kernels.h"
#include "scene/obj_loader.h"

using namespace rayvec;

namespace rayvec::variant {
void closest(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
             const Ray& ray, Hit& hit);
bool occluded(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
              const Ray& ray);
void closest_avx2(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                  const Ray& ray, Hit& hit);
bool occluded_avx2(const BvhArrays& bvh, const TriangleArrays& tris, const TriangleKernels& kernels,
                   const Ray& ray);
}

namespace {

double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Variant {
  std::string name;
  BvhOptions options;
  bool variant_traversal = false;
  Isa isa = Isa::avx512;
  std::unique_ptr<Bvh> bvh;
  std::vector<double> primary_s, incoherent_s, shadow_s;
  double build_s = 0;
};

Variant parse(const std::string& spec) {
  Variant v;
  const auto colon = spec.find(':');
  v.name = spec.substr(0, colon);
  std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
  while (!rest.empty()) {
    const auto comma = rest.find(',');
    const std::string kv = rest.substr(0, comma);
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    const auto eq = kv.find('=');
    const std::string k = kv.substr(0, eq);
    const double x = std::atof(kv.substr(eq + 1).c_str());
    if (k == "block" || k == "max_leaf") v.options.leaves_from_kernel = false;
    if (k == "block") v.options.sah.leaf_block = uint32_t(x);
    else if (k == "max_leaf") v.options.sah.max_leaf = uint32_t(x);
    else if (k == "trav") v.options.sah.traversal_cost = float(x);
    else if (k == "bins") v.options.sah.bins = int(x);
    else if (k == "width") v.options.width = int(x);
    else if (k == "trv") v.variant_traversal = x != 0;
    else if (k == "isa") v.isa = x == 2 ? Isa::avx2 : Isa::avx512;
    else if (k == "direct") v.options.direct_leaf = int(x);
    else { std::fprintf(stderr, "unknown key %s\n", k.c_str()); std::exit(2); }
  }
  if (!v.options.leaves_from_kernel) {  // keep the kernel-derived defaults for the other one
    if (v.options.sah.leaf_block == SahConfig{}.leaf_block) v.options.sah.leaf_block = 16;
    if (v.options.sah.max_leaf == SahConfig{}.max_leaf) v.options.sah.max_leaf = 32;
  }
  return v;
}

// Ordered closest-hit traversal in scalar code, mirroring bvh_traversal.inl, counting work.
struct Counts {
  double nodes = 0, leaves = 0, blocks = 0;
};
void count_closest(const Bvh& bvh, const TriangleKernels& k, const Ray& ray, Counts& c) {
  const BvhArrays& a = bvh.tree().arrays();
  const int n = int(a.width);
  const float* base = static_cast<const float*>(a.nodes);
  const std::size_t node_floats = n == 4 ? 32 : (n == 8 ? 64 : 112);  // 6n floats + n refs, aligned 64
  const float o[3] = {ray.org.x, ray.org.y, ray.org.z};
  const float rd[3] = {1.0f / ray.dir.x, 1.0f / ray.dir.y, 1.0f / ray.dir.z};
  struct Item {
    uint32_t ref;
    float t;
  };
  std::vector<Item> stack;
  Hit hit;
  uint32_t ref = 0;
  for (;;) {
    if (!(ref & kLeafFlag)) {
      c.nodes += 1;
      const float* node = base + std::size_t(ref) * node_floats;
      const auto* refs = reinterpret_cast<const uint32_t*>(node + 6 * n);
      std::vector<Item> hits;
      for (int j = 0; j < n; ++j) {
        float tn = ray.tmin, tf = hit.t < ray.tmax ? hit.t : ray.tmax;
        for (int ax = 0; ax < 3; ++ax) {
          float t0 = (node[ax * n + j] - o[ax]) * rd[ax], t1 = (node[(ax + 3) * n + j] - o[ax]) * rd[ax];
          if (t0 > t1) std::swap(t0, t1);
          tn = std::max(tn, t0 * (1 - 1e-5f));
          tf = std::min(tf, t1 * (1 + 1e-5f));
        }
        if (refs[j] != kEmptyRef && tn <= tf) hits.push_back({refs[j], tn});
      }
      std::sort(hits.begin(), hits.end(), [](const Item& x, const Item& y) { return x.t > y.t; });
      if (!hits.empty()) {
        ref = hits.back().ref;
        hits.pop_back();
        for (const Item& h : hits) stack.push_back(h);
        continue;
      }
    } else if (ref != kEmptyRef) {
      const uint32_t b = (ref >> 5) & (kMaxLeafBegin - 1), e = b + (ref & 31u) + 1;
      c.leaves += 1;
      c.blocks += (e - b + 15) / 16;
      k.closest(bvh.triangles().arrays(), b, e, ray, hit);
    }
    for (;;) {
      if (stack.empty()) return;
      if (stack.back().t <= hit.t) break;
      stack.pop_back();
    }
    ref = stack.back().ref;
    stack.pop_back();
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double wall_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double process_cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The build phases of Bvh's constructor, each timed on the wall clock and on the process CPU-time
// clock (all threads), median of `rounds`, at omp_get_max_threads() threads.
int phases(const TriangleMesh& mesh, int rounds) {
  const TraceConfig config{Isa::avx512, Intersector::mt};
  SahConfig sah;
  sah.leaf_block = 16;
  sah.max_leaf = 32;
#pragma omp parallel
  { volatile int x = 0; (void)x; }  // start the OpenMP threads before timing
  std::vector<double> w[4], c[4];
  for (int r = 0; r < rounds; ++r) {
    double w0 = wall_now(), c0 = process_cpu_now();
    const BinaryBvh binary = build_binned_sah(mesh, sah);
    double w1 = wall_now(), c1 = process_cpu_now();
    const WideBvh tree(binary, 8);
    double w2 = wall_now(), c2 = process_cpu_now();
    const TriangleSoA tris(mesh, binary.order);
    double w3 = wall_now(), c3 = process_cpu_now();
    w[0].push_back(w1 - w0); c[0].push_back(c1 - c0);
    w[1].push_back(w2 - w1); c[1].push_back(c2 - c1);
    w[2].push_back(w3 - w2); c[2].push_back(c3 - c2);
    w[3].push_back(w3 - w0); c[3].push_back(c3 - c0);
  }
  (void)config;
  const char* names[4] = {"binary SAH build", "collapse", "TriangleSoA fill", "total"};
  std::printf("%zu triangles, %d threads, median of %d (wall s / process CPU s)\n", mesh.size(),
              omp_get_max_threads(), rounds);
  for (int k = 0; k < 4; ++k)
    std::printf("  %-18s %8.4f %8.4f\n", names[k], median(w[k]), median(c[k]));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bvh_bench MODEL.obj [ROUNDS] VARIANT...\n");
    return 2;
  }
  const ObjModel model = load_obj(argv[1]);
  if (std::strcmp(argv[2], "phases") == 0) return phases(model.mesh, argc > 3 ? std::atoi(argv[3]) : 5);
  int first = 2, rounds = 5;
  if (std::strchr(argv[2], ':') == nullptr && std::atoi(argv[2]) > 0) rounds = std::atoi(argv[first++]);
  const TraceConfig config{Isa::avx512, Intersector::mt};
  const TriangleKernels& kernels = triangle_kernels(config.isa, config.intersector);
  std::vector<Variant> vs;
  for (int i = first; i < argc; ++i) vs.push_back(parse(argv[i]));
  for (Variant& v : vs) {
    const double t0 = cpu_now();
    v.bvh = std::make_unique<Bvh>(model.mesh, TraceConfig{v.isa, config.intersector}, v.options);
    v.build_s = cpu_now() - t0;
  }
  const int side = std::getenv("RV_SIDE") ? std::atoi(std::getenv("RV_SIDE")) : 1024;
  const BenchCamera cam = frame_mesh(model.mesh, side, side);
  const RaySet primary = primary_rays(cam);
  std::vector<Hit> hits(primary.rays.size());
  for (std::size_t i = 0; i < hits.size(); ++i) hits[i] = vs[0].bvh->closest(primary.rays[i]);
  const RaySet incoherent = incoherent_rays(cam, model.mesh, primary, hits);
  const RaySet shadow = shadow_rays(cam, primary, hits);
  if (std::getenv("RV_PRIMARY_MISSES")) {  // keep only the primary rays that miss (1) or hit (2)
    const bool keep_hits = std::atoi(std::getenv("RV_PRIMARY_MISSES")) == 2;
    RaySet kept;
    for (std::size_t i = 0; i < hits.size(); ++i)
      if (hits[i].hit() == keep_hits) {
        kept.rays.push_back(primary.rays[i]);
        kept.pixel.push_back(primary.pixel[i]);
      }
    const_cast<RaySet&>(primary) = kept;
  }
  std::vector<Hit> out(primary.rays.size());
  std::vector<uint8_t> occluded(shadow.rays.size());
  uint64_t sums[3] = {0, 0, 0};
  auto trace_shadow = [&](const Variant& v) {
    const double t0 = cpu_now();
    const BvhKernels& tk = bvh_kernels(v.isa, v.bvh->tree().width());
    const TriangleKernels& kernels = triangle_kernels(v.isa, config.intersector);
    for (std::size_t i = 0; i < shadow.rays.size(); ++i)
      occluded[i] = v.variant_traversal
                        ? (v.isa == Isa::avx2 ? variant::occluded_avx2 : variant::occluded)(
                              v.bvh->tree().arrays(), v.bvh->triangles().arrays(), kernels, shadow.rays[i])
                        : tk.occluded(v.bvh->tree().arrays(), v.bvh->triangles().arrays(), kernels,
                                      shadow.rays[i], nullptr);
    return cpu_now() - t0;
  };
  auto trace = [&](const Variant& v, const RaySet& set) {
    const double t0 = cpu_now();
    const BvhKernels& tk = bvh_kernels(v.isa, v.bvh->tree().width());
    const TriangleKernels& kernels = triangle_kernels(v.isa, config.intersector);
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
      Hit h;
      if (v.variant_traversal)
        (v.isa == Isa::avx2 ? variant::closest_avx2 : variant::closest)(
            v.bvh->tree().arrays(), v.bvh->triangles().arrays(), kernels, set.rays[i], h);
      else
        tk.closest(v.bvh->tree().arrays(), v.bvh->triangles().arrays(), kernels, set.rays[i], h);
      out[i] = h;
    }
    return cpu_now() - t0;
  };
  for (int r = 0; r < rounds + 1; ++r) {
    for (Variant& v : vs) {
      const double p = trace(v, primary);
      if (r == 0) sums[0] = hit_checksum(primary, out);
      else if (hit_checksum(primary, out) != sums[0]) std::printf("%s: primary checksum differs\n", v.name.c_str());
      const double q = trace(v, incoherent);
      if (r == 0 && &v == &vs[0]) sums[1] = hit_checksum(incoherent, out);
      else if (hit_checksum(incoherent, out) != sums[1]) std::printf("%s: incoherent checksum differs\n", v.name.c_str());
      const double s = trace_shadow(v);
      if (r == 0 && &v == &vs[0]) sums[2] = occluded_checksum(shadow, occluded);
      else if (occluded_checksum(shadow, occluded) != sums[2]) std::printf("%s: shadow checksum differs\n", v.name.c_str());
      if (r > 0) {  // round 0 warms up
        v.primary_s.push_back(p);
        v.incoherent_s.push_back(q);
        v.shadow_s.push_back(s);
        if (std::getenv("RV_ROUNDS"))  // every round's times, to see the VM's phases
          std::printf("round %d %s primary %.4f incoherent %.4f shadow %.4f\n", r, v.name.c_str(), p, q, s);
      }
    }
  }
  std::printf("%zu triangles, %zu primary / %zu incoherent / %zu shadow rays, %d rounds (median thread CPU s)\n",
              model.mesh.size(), primary.rays.size(), incoherent.rays.size(), shadow.rays.size(), rounds);
  std::printf("%-14s %7s %7s %6s %8s %8s %6s %6s | %7s %7s %6s | %7s %7s %6s\n", "variant", "nodes", "leaves",
              "depth", "build_s", "prim_s", "ratio", "", "p.nodes", "p.leaf", "p.blk", "i.nodes", "i.leaf",
              "i.blk");
  const double p0 = median(vs[0].primary_s), q0 = median(vs[0].incoherent_s), s0 = median(vs[0].shadow_s);
  for (Variant& v : vs) {
    Counts cp, ci;
    const std::size_t step = 7;  // a sample of the rays is enough for the averages
    std::size_t np = 0, ni = 0;
    for (std::size_t i = 0; i < primary.rays.size(); i += step, ++np) count_closest(*v.bvh, kernels, primary.rays[i], cp);
    for (std::size_t i = 0; i < incoherent.rays.size(); i += step, ++ni) count_closest(*v.bvh, kernels, incoherent.rays[i], ci);
    const double p = median(v.primary_s), q = median(v.incoherent_s);
    std::printf("%-14s %7u %7u %6u %8.3f %8.4f %6.3f inc %6.4f %6.3f | %7.2f %7.2f %6.2f | %7.2f %7.2f %6.2f\n",
                v.name.c_str(), v.bvh->tree().node_count(), v.bvh->tree().leaf_count(), v.bvh->tree().depth(),
                v.build_s, p, p0 / p, q, q0 / q, cp.nodes / np, cp.leaves / np, cp.blocks / np, ci.nodes / ni,
                ci.leaves / ni, ci.blocks / ni);
  }
  std::printf("shadow (any hit), median thread CPU s and ratio to the first variant:\n");
  for (Variant& v : vs) std::printf("  %-14s %8.4f %6.3f\n", v.name.c_str(), median(v.shadow_s), s0 / median(v.shadow_s));
}
