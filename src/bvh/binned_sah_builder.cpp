#include "bvh/binned_sah_builder.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "scene/mesh.h"

namespace rayvec {
namespace {

constexpr int kMaxBins = 64;

struct Bin {
  BBox box;
  uint32_t count = 0;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = std::numeric_limits<float>::infinity();
  BBox left, right;
};

class Builder {
 public:
  Builder(const TriangleMesh& mesh, const SahConfig& config, BinaryBvh& out)
      : config_(config), out_(out) {
    const std::size_t n = mesh.size();
    boxes_.resize(n);
    centroids_.resize(n);
    out_.order.resize(n);
    const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < count; ++i) {
      BBox b;
      for (int c = 0; c < 3; ++c) b.grow(mesh.vertex(std::size_t(i), c));
      boxes_[i] = b;
      centroids_[i] = b.center();
      out_.order[i] = static_cast<uint32_t>(i);
    }
    // at most 2n - 1 nodes; children are allocated in pairs
    out_.nodes.resize(n == 0 ? 0 : 2 * n - 1);
    next_node_.store(1);
  }

  void run() {
    if (boxes_.empty()) return;
    BBox root;
    for (const BBox& b : boxes_) root.grow(b);
#pragma omp parallel
#pragma omp single nowait
    build(0, 0, static_cast<uint32_t>(boxes_.size()), root, 0);
    out_.nodes.resize(next_node_.load());
  }

 private:
  // Bin of a centroid coordinate; NaN and out-of-range values are clamped to the end bins.
  static int bin_of(float c, float lo, float scale, int bins) {
    const float f = (c - lo) * scale;
    if (!(f > 0.0f)) return 0;
    const int k = f >= float(bins) ? bins - 1 : int(f);
    return k < bins - 1 ? k : bins - 1;
  }

  Split find_split(uint32_t begin, uint32_t end, const BBox& cbox, int bins) const {
    Split best;
    const Vec3f ext = cbox.extent();
    for (int axis = 0; axis < 3; ++axis) {
      if (!(ext[axis] > 0.0f)) continue;
      const float scale = float(bins) / ext[axis];
      Bin bin[kMaxBins];
      for (uint32_t i = begin; i < end; ++i) {
        const uint32_t p = out_.order[i];
        Bin& b = bin[bin_of(centroids_[p][axis], cbox.lo[axis], scale, bins)];
        b.box.grow(boxes_[p]);
        ++b.count;
      }
      // sweep from the right, then from the left
      float right_area[kMaxBins];
      uint32_t right_count[kMaxBins];
      BBox acc;
      uint32_t n = 0;
      for (int k = bins - 1; k > 0; --k) {
        acc.grow(bin[k].box);
        n += bin[k].count;
        right_area[k] = acc.half_area();
        right_count[k] = n;
      }
      BBox left;
      uint32_t nl = 0;
      for (int k = 0; k < bins - 1; ++k) {
        left.grow(bin[k].box);
        nl += bin[k].count;
        const uint32_t nr = right_count[k + 1];
        if (nl == 0 || nr == 0) continue;
        const float cost = left.half_area() * leaf_cost(nl) + right_area[k + 1] * leaf_cost(nr);
        if (cost < best.cost) {
          best.cost = cost;
          best.axis = axis;
          best.bin = k;
        }
      }
      if (best.axis == axis) {  // boxes of the chosen split
        best.left = BBox{};
        best.right = BBox{};
        for (int k = 0; k < bins; ++k) (k <= best.bin ? best.left : best.right).grow(bin[k].box);
      }
    }
    return best;
  }

  float leaf_cost(uint32_t n) const {
    return float((n + config_.leaf_block - 1) / config_.leaf_block);
  }

  void make_leaf(uint32_t node, uint32_t begin, uint32_t end, const BBox& box) {
    std::sort(out_.order.begin() + begin, out_.order.begin() + end);  // ids increase in a leaf
    out_.nodes[node] = BinaryNode{box, begin, end - begin};
  }

  void build(uint32_t node, uint32_t begin, uint32_t end, const BBox& box, int depth) {
    const uint32_t n = end - begin;
    if (n <= 1) return make_leaf(node, begin, end, box);
    BBox cbox;
    for (uint32_t i = begin; i < end; ++i) cbox.grow(centroids_[out_.order[i]]);

    uint32_t mid = begin;
    BBox left_box, right_box;
    const Split split = depth < config_.max_sah_depth
                            ? find_split(begin, end, cbox, std::clamp(config_.bins, 2, kMaxBins))
                            : Split{};
    if (split.axis >= 0) {
      const float area = box.half_area();
      const float split_cost = config_.traversal_cost + (area > 0.0f ? split.cost / area : 0.0f);
      if (n <= config_.max_leaf && leaf_cost(n) <= split_cost) return make_leaf(node, begin, end, box);
      const int axis = split.axis;
      const int bins = std::clamp(config_.bins, 2, kMaxBins);
      const float scale = float(bins) / cbox.extent()[axis];
      const float lo = cbox.lo[axis];
      auto* first = out_.order.data() + begin;
      auto* pivot = std::partition(first, out_.order.data() + end, [&](uint32_t p) {
        return bin_of(centroids_[p][axis], lo, scale, bins) <= split.bin;
      });
      mid = begin + uint32_t(pivot - first);
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
      std::nth_element(out_.order.begin() + begin, out_.order.begin() + mid,
                       out_.order.begin() + end, [&](uint32_t a, uint32_t b) {
                         const float ca = centroids_[a][axis], cb = centroids_[b][axis];
                         return ca < cb || (ca == cb && a < b);
                       });
      left_box = range_box(begin, mid);
      right_box = range_box(mid, end);
    }
    const uint32_t left = next_node_.fetch_add(2);
    out_.nodes[node] = BinaryNode{box, left, 0};
    if (n >= config_.task_threshold) {
#pragma omp task firstprivate(left, begin, mid, left_box, depth)
      build(left, begin, mid, left_box, depth + 1);
      build(left + 1, mid, end, right_box, depth + 1);
#pragma omp taskwait
    } else {
      build(left, begin, mid, left_box, depth + 1);
      build(left + 1, mid, end, right_box, depth + 1);
    }
  }

  BBox range_box(uint32_t begin, uint32_t end) const {
    BBox b;
    for (uint32_t i = begin; i < end; ++i) b.grow(boxes_[out_.order[i]]);
    return b;
  }

  const SahConfig& config_;
  BinaryBvh& out_;
  std::vector<BBox> boxes_;
  std::vector<Vec3f> centroids_;
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
