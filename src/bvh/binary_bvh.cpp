#include "bvh/binary_bvh.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <memory>
#include <new>

#include "bvh/build_prim.h"
#include "bvh/prim_partition.h"
#include "bvh/sah_bins.h"
#include "bvh/spatial_split.h"
#include "geometry/triangle_mesh.h"
#include "platform/large_buffer.h"
#include "simd/float4_sse.h"

namespace rayvec {
namespace {

constexpr uint32_t kParallelBinning = 2048;        // ranges this large may bin in parallel chunks
constexpr uint32_t kParallelPartition = 1u << 16;  // ... and partition in parallel chunks
constexpr int kBinningChunks = 4;
// ranges this large bin alternate primitives into kBinSets sets of bins (Builder::bin_range)
constexpr uint32_t kInterleavedBinning = 256;
constexpr int kBinSets = 4;
// fewer triangles: build on the calling thread (a 1,000-triangle build takes ~0.3 ms, a parallel
// region a few µs when the team's threads are awake)
constexpr std::size_t kParallelBuild = 1024;
// Spatial splits (SahConfig::split_budget): bins per axis, and how much the children of an object
// split must overlap for one to be tried: their common box's area relative to the root's (Stich et
// al.'s α, which keeps splits out of the tree's small bottom nodes), to the node's own (which
// keeps the search off nodes whose object split is already nearly disjoint, as on a mesh of small,
// even triangles), and its thickness along the split axis relative to the node's extent there (a
// thin slab is the overlap of a curved surface cut across, made by triangles that barely straddle
// the cut: large in area, yet no spatial split pays for it; benchmarks.md#decision-spatial-splits)
constexpr int kSpatialBins = 16;
constexpr float kSplitOverlap = 1e-5f;
constexpr float kSplitNodeOverlap = 0.3f;
constexpr float kSplitAxisOverlap = 0.05f;

using Prim = BuildPrim;
using namespace sah_bins;

class Builder {
 public:
  Builder(const TriangleMesh& mesh, const SahConfig& config, BinaryBvh& out)
      : config_(config),
        bins_(std::clamp(config.bins, 2, kMaxBins)),
        out_(out),
        splitter_(mesh, kSpatialBins, config.leaf_block) {
    const std::size_t n = mesh.size();
    // room for the references spatial splits add (split_budget of n at most)
    const double budget = std::clamp(double(config.split_budget), 0.0, 1.0);
    const std::size_t capacity = n + std::size_t(double(n) * budget);
    // uninitialized (no serial zeroing of 32 bytes a triangle): the parallel loop writes each one
    prims_buffer_ = allocate_large_buffer(sizeof(Prim) * capacity);
    prims_ = static_cast<Prim*>(prims_buffer_.get());
    count_ = n;
    capacity_ = capacity;
    out_.order.resize(capacity);
    const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (n >= kParallelBuild)
    for (std::int64_t i = 0; i < count; ++i) {
      BinBox b;
      for (int c = 0; c < 3; ++c) {
        const Vec3f v = mesh.vertex(std::size_t(i), c);
        for (int a = 0; a < 3; ++a) {
          b.lo[a] = min_keep(b.lo[a], v[a]);
          b.hi[a] = max_keep(b.hi[a], v[a]);
        }
      }
      prims_[i] = Prim{{b.lo[0], b.lo[1], b.lo[2]}, uint32_t(i), {b.hi[0], b.hi[1], b.hi[2]}, 0.0f};
    }
    // at most 2n - 1 nodes (children are allocated in pairs), uninitialized: the tree uses a few
    // percent of them, so only the pages written are ever touched (zeroing 2n nodes serially cost
    // more than the parallel parts of the build it preceded); run() copies out the used prefix
    if (n > 0)
      nodes_.reset(static_cast<BinaryNode*>(::operator new(sizeof(BinaryNode) * (2 * capacity - 1))));
  }

  void run() {
    if (count_ == 0) return;
    const auto n = static_cast<uint32_t>(count_);
    const BBox root = range_box(0, n, false, 0);
    root_area_ = root.half_area();
#pragma omp parallel if (n >= kParallelBuild)
#pragma omp single nowait
    build(0, 0, n, uint32_t(capacity_), root, 0);
    out_.nodes.assign(nodes_.get(), nodes_.get() + next_node_.load());
    nodes_.reset();
    if (capacity_ > count_) close_gaps();
  }

 private:
  struct Range {
    float lo[3], scale[3];
  };

  // Whether a range of n primitives at this depth is worked on in chunks as tasks: only while the
  // tree has fewer ranges at this depth than threads (2^depth < threads). Below that the subtrees
  // alone keep every thread busy, and chunking costs more than it gains (the chunked partition
  // swaps the misplaced primitives after partitioning the chunks; the chunked binning merges 4
  // sets of bins). `threshold`: kParallelBinning
  // for the binning and the bounds, kParallelPartition for the partition.
  bool chunked(uint32_t n, int depth, uint32_t threshold = kParallelBinning) const {
    return n >= threshold && depth < 30 && (1 << depth) < threads_;
  }

  // All three axes of a primitive at once in 4 lanes: centroid, bin (bin_of's arithmetic, lane by
  // lane, so the partition's scalar bin_of agrees), then one min and max per axis's bin. Lane 3
  // holds the id's bits in `lo` and is masked to 0 before any arithmetic (as a float an id is
  // usually a denormal, slow to compute with), so an occupied bin's lane 3 is 0 (SweepBox).
  // Neighbouring primitives (a mesh's order, and a partition's) mostly fall in the same bins, so
  // each bin's load-min-store waits on the previous primitive's store: large ranges bin alternate
  // primitives into kBinSets sets of bins, merged at the end (min, max and sums are exact, so the
  // bins are the same).
  void bin_range(uint32_t begin, uint32_t end, const Range& r, Bins& out) const {
    using sse::Float4;
    const Float4 rlo = Float4::set(r.lo[0], r.lo[1], r.lo[2], 0.0f);
    const Float4 rscale = Float4::set(r.scale[0], r.scale[1], r.scale[2], 0.0f);
    const Float4 half = Float4::broadcast(0.5f), zero = Float4::broadcast(0.0f);
    const Float4 last = Float4::broadcast(float(bins_ - 1));
    const auto add = [&](const Prim& p, Bins& to) {
      const Float4 lo = Float4::load(p.lo).xyz(), hi = Float4::load(p.hi);
      const Float4 c = (lo + hi) * half;
      int32_t k[4];
      vmin(vmax((c - rlo) * rscale, zero), last).store_truncated(k);
      for (int a = 0; a < 3; ++a) {
        float* b = to.box[a][k[a]];
        vmin(lo, Float4::load(b)).store(b);
        vmax(hi, Float4::load(b + 4)).store(b + 4);
        ++to.count[a][k[a]];
      }
    };
    out.clear(bins_);
    uint32_t i = begin;
    if (end - begin >= kInterleavedBinning) {
      Bins more[kBinSets - 1];
      for (Bins& m : more) m.clear(bins_);
      for (; i + kBinSets <= end; i += kBinSets) {
        add(prims_[i], out);
        for (int s = 1; s < kBinSets; ++s) add(prims_[i + uint32_t(s)], more[s - 1]);
      }
      for (const Bins& m : more) out.grow(m, bins_);
    }
    for (; i < end; ++i) add(prims_[i], out);
  }

  Split find_split(uint32_t begin, uint32_t end, const BBox& cbox, int depth) const {
    const Vec3f ext = cbox.extent();
    Range r;
    for (int a = 0; a < 3; ++a) {
      r.lo[a] = cbox.lo[a];
      r.scale[a] = ext[a] > 0.0f ? float(bins_) / ext[a] : 0.0f;
    }
    Bins bins;
    if (chunked(end - begin, depth)) {  // the top of the tree: bin chunks as tasks, merge
      Bins part[kBinningChunks];
      const uint32_t step = (end - begin + kBinningChunks - 1) / kBinningChunks;
      for (int c = 0; c < kBinningChunks; ++c) {
        const uint32_t b = begin + uint32_t(c) * step, e = std::min(end, b + step);
#pragma omp task shared(part, r) firstprivate(b, e, c)
        bin_range(b, e, r, part[c]);
      }
#pragma omp taskwait
      bins = part[0];
      for (int c = 1; c < kBinningChunks; ++c) bins.grow(part[c], bins_);
    } else {
      bin_range(begin, end, r, bins);
    }
    return cheapest_split(bins, bins_, ext, [this](uint32_t count) { return leaf_cost(count); });
  }

  // ceil(n / leaf_block), by a shift for the usual power-of-two block (a division on every step of
  // the sweep was a visible part of the build)
  float leaf_cost(uint32_t n) const {
    const uint32_t b = config_.leaf_block;
    return float(leaf_shift_ >= 0 ? (n + b - 1) >> leaf_shift_ : (n + b - 1) / b);
  }

  void make_leaf(uint32_t node, uint32_t begin, uint32_t end, const BBox& box) {
    for (uint32_t i = begin; i < end; ++i) out_.order[i] = prims_[i].id;
    std::sort(out_.order.begin() + begin, out_.order.begin() + end);  // ids increase in a leaf
    new (nodes_.get() + node) BinaryNode{box, begin, end - begin};
  }

  void grow_range(uint32_t begin, uint32_t end, bool centroids, BinBox& b) const {
    for (uint32_t i = begin; i < end; ++i) {
      const Prim& p = prims_[i];
      for (int a = 0; a < 3; ++a) {
        const float lo = centroids ? p.centroid(a) : p.lo[a], hi = centroids ? p.centroid(a) : p.hi[a];
        b.lo[a] = min_keep(b.lo[a], lo);
        b.hi[a] = max_keep(b.hi[a], hi);
      }
    }
  }

  // Bounds of the boxes (or centroids) of a range; large ranges in chunks as tasks (min and max
  // are exact, so the result does not depend on the chunking).
  BBox range_box(uint32_t begin, uint32_t end, bool centroids, int depth) const {
    BinBox b;
    if (chunked(end - begin, depth)) {
      BinBox part[kBinningChunks];
      const uint32_t step = (end - begin + kBinningChunks - 1) / kBinningChunks;
      for (int c = 0; c < kBinningChunks; ++c) {
        const uint32_t cb = begin + uint32_t(c) * step, ce = std::min(end, cb + step);
#pragma omp task shared(part) firstprivate(cb, ce, c, centroids)
        grow_range(cb, ce, centroids, part[c]);
      }
#pragma omp taskwait
      for (const BinBox& p : part) b.grow(p);
    } else {
      grow_range(begin, end, centroids, b);
    }
    return b.box();
  }

  // Moves the primitives of [begin, end) for which goes_left(p) holds before the others
  // (bvh/prim_partition.h), in chunks as tasks where chunked(…, kParallelPartition).
  template <class F>
  uint32_t partition_range(uint32_t begin, uint32_t end, int depth, const F& goes_left, BBox (&cbox)[2]) {
    if (chunked(end - begin, depth, kParallelPartition))
      return prim_partition::chunked(prims_, begin, end, goes_left, cbox);
    return prim_partition::serial(prims_, begin, end, goes_left, cbox);
  }

  // With room for spatial splits the ranges leave gaps (each range's unused room): the leaves are
  // moved together, in order, so `order` holds exactly the leaves' slots.
  void close_gaps() {
    std::vector<std::pair<uint32_t, uint32_t>> leaves;  // (first, node)
    for (uint32_t k = 0; k < out_.nodes.size(); ++k)
      if (out_.nodes[k].leaf()) leaves.emplace_back(out_.nodes[k].first, k);
    std::sort(leaves.begin(), leaves.end());
    uint32_t next = 0;
    for (const auto& [first, k] : leaves) {
      BinaryNode& leaf = out_.nodes[k];
      std::copy(out_.order.begin() + first, out_.order.begin() + first + leaf.count,
                out_.order.begin() + next);
      leaf.first = next;
      next += leaf.count;
    }
    out_.order.resize(next);
  }

  // Whether the children of an object split overlap enough for a spatial split to be tried
  // (kSplitOverlap, kSplitNodeOverlap, kSplitAxisOverlap).
  bool overlapping(const Split& split, const BBox& box) const {
    BBox common;
    for (int a = 0; a < 3; ++a) {
      common.lo[a] = std::max(split.left.lo[a], split.right.lo[a]);
      common.hi[a] = std::min(split.left.hi[a], split.right.hi[a]);
    }
    const float area = common.half_area();
    const int a = split.axis;
    const float thickness = common.hi[a] - common.lo[a];
    return area > kSplitOverlap * root_area_ && area > kSplitNodeOverlap * box.half_area() &&
           thickness > kSplitAxisOverlap * (box.hi[a] - box.lo[a]);
  }

  // Builds the subtree of the references [begin, end) into `node`; [end, cap) is room the subtree
  // may fill with the references its spatial splits add.
  void build(uint32_t node, uint32_t begin, uint32_t end, uint32_t cap, const BBox& box, int depth,
             const BBox* cbox_known = nullptr) {
    const uint32_t n = end - begin;
    if (n <= 1) return make_leaf(node, begin, end, box);
    // A range whose leaf costs no more than one node visit (the smallest ranges) is a leaf whatever
    // its split costs: the test below is leaf_cost(n) <= traversal_cost + cost / area, and with a
    // finite area the children's areas are finite and no larger, so the second term is >= 0 (or 0
    // when area is 0). Infinite or NaN areas take the full path.
    if (n <= config_.max_leaf && leaf_cost(n) <= config_.traversal_cost && box.half_area() < kInf)
      return make_leaf(node, begin, end, box);
    const BBox cbox = cbox_known ? *cbox_known : range_box(begin, end, true, depth);

    uint32_t mid = begin;
    BBox left_box, right_box;
    BBox child_cbox[2];
    bool have_child_cbox = false;
    const Split split = depth < config_.max_sah_depth ? find_split(begin, end, cbox, depth) : Split{};
    SpatialSplit spatial;
    if (cap > end && split.axis >= 0 && overlapping(split, box)) {
      spatial = splitter_.find(prims_ + begin, n, box, cap - end);
      if (spatial.cost >= split.cost) spatial.axis = -1;
    }
    if (split.axis >= 0) {
      const float area = box.half_area();
      const float cost = spatial.axis >= 0 ? spatial.cost : split.cost;
      const float split_cost = config_.traversal_cost + (area > 0.0f ? cost / area : 0.0f);
      if (n <= config_.max_leaf && leaf_cost(n) <= split_cost) return make_leaf(node, begin, end, box);
    }
    if (spatial.axis >= 0) {
      std::vector<Prim> right;
      right.reserve(spatial.right);
      const uint32_t nl = splitter_.partition(prims_ + begin, n, box, spatial, right);
      const auto nr = uint32_t(right.size());
      if (nl > 0 && nr > 0) {
        // the room left is shared in proportion to the sides' references
        const uint32_t room = cap - begin - nl - nr;
        const uint32_t right_begin = begin + nl + uint32_t(uint64_t(room) * nl / (nl + nr));
        std::copy(right.begin(), right.end(), prims_ + right_begin);
        return split_node(
            node, box, {begin, begin + nl, right_begin, range_box(begin, begin + nl, false, depth)},
            {right_begin, right_begin + nr, cap, range_box(right_begin, right_begin + nr, false, depth)},
            depth, nullptr);
      }
      // every reference landed on one side (whole or clipped): split by object below
      if (nl == 0) std::copy(right.begin(), right.end(), prims_ + begin);
    }
    if (split.axis >= 0) {
      const int axis = split.axis;
      const float lo = cbox.lo[axis], scale = float(bins_) / cbox.extent()[axis];
      // bin_of(centroid) <= split.bin, as one comparison
      const float threshold = right_threshold(lo, scale, bins_, split.bin);
      mid = partition_range(
          begin, end, depth, [axis, threshold](const Prim& p) { return !(p.centroid(axis) >= threshold); },
          child_cbox);
      have_child_cbox = true;
      left_box = split.left;
      right_box = split.right;
    } else if (n <= config_.max_leaf) {
      return make_leaf(node, begin, end, box);
    }
    if (mid == begin || mid == end) {
      // no usable SAH split (equal centroids, or too deep): object median on the widest axis, which
      // halves the range so the depth stays logarithmic
      const Vec3f e = cbox.extent();
      const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
      mid = begin + n / 2;
      std::nth_element(prims_ + begin, prims_ + mid, prims_ + end, [&](const Prim& a, const Prim& b) {
        const float ca = a.centroid(axis), cb = b.centroid(axis);
        return ca < cb || (ca == cb && a.id < b.id);
      });
      left_box = range_box(begin, mid, false, depth);
      right_box = range_box(mid, end, false, depth);
      have_child_cbox = false;
    }
    // the room after the range is shared in proportion to the sides' references
    const uint32_t shift = uint32_t(uint64_t(cap - end) * (mid - begin) / n);
    // the right side moves up by `shift`: only its first min(shift, size) references need to move
    // (to its new end), since the order inside a range does not matter
    if (shift != 0) {
      const uint32_t moved = std::min(shift, end - mid);
      std::copy(prims_ + mid, prims_ + mid + moved, prims_ + end + shift - moved);
    }
    split_node(node, box, {begin, mid, mid + shift, left_box}, {mid + shift, end + shift, cap, right_box},
               depth, have_child_cbox ? child_cbox : nullptr);
  }

  struct Child {
    uint32_t begin, end, cap;
    BBox box;
  };

  // Makes `node` an inner node over the two children and builds them (as tasks when large).
  // child_cbox: the children's centroid bounds when known, else null.
  void split_node(uint32_t node, const BBox& box, const Child& l, const Child& r, int depth,
                  const BBox* child_cbox) {
    const uint32_t left = next_node_.fetch_add(2);
    new (nodes_.get() + node) BinaryNode{box, left, 0};
    const bool known = child_cbox != nullptr;
    const BBox lc = known ? child_cbox[0] : BBox{}, rc = known ? child_cbox[1] : BBox{};
    if (l.end - l.begin + r.end - r.begin >= config_.task_threshold) {
      // Both halves as tasks: a taskwait waits for every child of the current task, so a right
      // half built in place would, at its first binning taskwait, also wait for (and usually run)
      // the whole left half, which serialised the build. Nothing waits for them here: the node is
      // written, and the parallel region's closing barrier waits for every task. A thread that
      // waited here could run only its own children (libgomp's taskwait), so it sat idle while
      // the other thread built a stolen half alone; at the barrier it runs any task.
#pragma omp task firstprivate(left, l, depth, lc, known)
      build(left, l.begin, l.end, l.cap, l.box, depth + 1, known ? &lc : nullptr);
#pragma omp task firstprivate(left, r, depth, rc, known)
      build(left + 1, r.begin, r.end, r.cap, r.box, depth + 1, known ? &rc : nullptr);
    } else {
      build(left, l.begin, l.end, l.cap, l.box, depth + 1, known ? &lc : nullptr);
      build(left + 1, r.begin, r.end, r.cap, r.box, depth + 1, known ? &rc : nullptr);
    }
  }

  const SahConfig& config_;
  const int threads_ = omp_get_max_threads();
  const int bins_;
  // log2(leaf_block) when it is a power of two, else -1
  const int leaf_shift_ = config_.leaf_block != 0 && std::has_single_bit(config_.leaf_block)
                              ? std::countr_zero(config_.leaf_block)
                              : -1;
  BinaryBvh& out_;
  // primitive records: a LargeBuffer, uninitialized; the constructor's parallel loop writes every one
  LargeBuffer prims_buffer_;
  Prim* prims_ = nullptr;
  std::size_t count_ = 0, capacity_ = 0;
  float root_area_ = 0;
  SpatialSplitter splitter_;
  struct OperatorDelete {
    void operator()(BinaryNode* p) const { ::operator delete(p); }
  };
  std::unique_ptr<BinaryNode, OperatorDelete> nodes_;  // 2n − 1 slots, see the constructor
  std::atomic<uint32_t> next_node_{1};
};

}  // namespace

BinaryBvh build_binned_sah(const TriangleMesh& mesh, const SahConfig& config) {
  BinaryBvh out;
  Builder builder(mesh, config, out);
  builder.run();
  return out;
}

}  // namespace rayvec
