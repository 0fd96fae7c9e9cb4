#include "bench/paper_shares.h"

#include <algorithm>
#include <bit>

#include "accel/accelerator.h"
#include "bench/paper_scene.h"

namespace rayvec {

bool same_hit(const Hit& a, const Hit& b) {
  return a.tri == b.tri && (a.tri < 0 || (a.t == b.t && a.u == b.u && a.v == b.v));
}

uint64_t hits_checksum(std::span<const Hit> hits, uint64_t first_ray) {
  uint64_t sum = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const uint64_t key = uint64_t(std::bit_cast<uint32_t>(hits[i].t)) << 32 | uint32_t(hits[i].tri + 1);
    sum += (first_ray + i + 1) * key;  // unsigned: wraps mod 2^64
  }
  return sum;
}

double share_imbalance(const std::vector<Table1Share>& shares, Timing Table1Share::*column) {
  double slowest = 0, sum = 0;
  for (const Table1Share& s : shares) {
    slowest = std::max(slowest, (s.*column).seconds);
    sum += (s.*column).seconds;
  }
  return sum > 0 ? slowest / (sum / double(shares.size())) : 0.0;
}

namespace {

Timing slowest_of(const std::vector<Table1Share>& shares, Timing Table1Share::*column) {
  Timing out;
  out.repeats = shares.empty() ? 0 : (shares.front().*column).repeats;
  for (const Table1Share& s : shares) {
    const Timing& t = s.*column;
    out.seconds = std::max(out.seconds, t.seconds);
    out.repeats = std::min(out.repeats, t.repeats);
    out.ghz += t.ghz / double(shares.size());
    out.fma_per_cycle += t.fma_per_cycle / double(shares.size());
  }
  return out;
}

}  // namespace

Table1Result combine_table1_shares(const PaperModel& model, uint32_t side, bool baselines,
                                   std::vector<Table1Share> shares, std::span<const Hit> hits) {
  Table1Result r;
  r.model = model;
  r.side = side;
  r.baselines = baselines;
  r.original = slowest_of(shares, &Table1Share::original);
  r.optimized = slowest_of(shares, &Table1Share::optimized);
  r.vec_paper = slowest_of(shares, &Table1Share::vec_paper);
  r.vec_mt = slowest_of(shares, &Table1Share::vec_mt);
  for (const Table1Share& s : shares) {
    r.mismatches += s.mismatches;
    r.mt_differences += s.mt_differences;
  }
  for (const Hit& h : hits) r.hits += h.hit();
  r.checksum = hits_checksum(hits);
  r.shares = std::move(shares);
  return r;
}

std::vector<uint64_t> check_sample(const std::vector<Table1Share>& shares) {
  std::vector<uint64_t> out;
  if (shares.empty()) return out;
  const uint64_t n = shares.back().last, stride = shares.size();
  for (uint64_t i = 0; i < n; i += stride) out.push_back(i);
  for (const Table1Share& s : shares)
    if (s.last > s.first) {
      out.push_back(s.first);
      out.push_back(s.last - 1);
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

uint64_t retrace_differences(const PaperModel& model, uint32_t side, Isa isa,
                             std::span<const uint64_t> sample, std::span<const Hit> gathered) {
  const RayBatch all = paper_camera_rays(side);
  std::vector<Ray> rays;
  rays.reserve(sample.size());
  for (uint64_t i : sample) rays.push_back(all[std::size_t(i)]);
  std::vector<Hit> hits(rays.size());
  const auto accel =
      make_accelerator(AccelKind::brute, paper_triangles(model.triangles), {isa, Intersector::paper});
  accel->closest_stream(rays.data(), hits.data(), rays.size());
  uint64_t differ = 0;
  for (std::size_t k = 0; k < sample.size(); ++k)
    differ += sample[k] >= gathered.size() || !same_hit(hits[k], gathered[std::size_t(sample[k])]);
  return differ;
}

}  // namespace rayvec
