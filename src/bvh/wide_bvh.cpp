#include "bvh/wide_bvh.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include "platform/side_by_side.h"

namespace rayvec {
namespace {

// Why both rules of CollapseRule: neither wins on every tree. On the bench meshes the count rule
// cuts node visits per ray for 16-wide trees and raises them for 8-wide ones
// (benchmarks.md#decision-collapse-rule). So by default WideBvh collapses both ways and keeps the
// tree of the lower SAH node cost (the expected node visits of a random ray up to a factor; the
// leaves are the same either way).

constexpr std::size_t kParallelCollapseNodes = 256;  // binary nodes

// The slots a binary subtree's leaves lie in: [begin, end) from its first leaf's first slot to its
// last leaf's end (leaves are in tree order, so nothing else lies between them but padding).
struct SlotSpan {
  uint32_t begin, end;
};

// out[k] for every binary node k: leaf(node) at leaves, combine(out[left], out[right]) above,
// children before parents (iterative post-order: the binary tree may be deep).
template <class T, class Leaf, class Combine>
std::vector<T> fold_subtrees(const BinaryBvh& tree, Leaf leaf, Combine combine) {
  const std::vector<BinaryNode>& nodes = tree.nodes;
  std::vector<T> out(nodes.size());
  if (nodes.empty()) return out;
  std::vector<std::pair<uint32_t, bool>> stack{{0, false}};
  while (!stack.empty()) {
    const auto [k, children_done] = stack.back();
    stack.pop_back();
    const BinaryNode& n = nodes[k];
    if (n.leaf()) {
      out[k] = leaf(n);
    } else if (children_done) {
      out[k] = combine(out[n.first], out[n.first + 1]);
    } else {
      stack.push_back({k, true});
      stack.push_back({n.first, false});
      stack.push_back({n.first + 1, false});
    }
  }
  return out;
}

std::vector<SlotSpan> subtree_spans(const BinaryBvh& tree) {
  return fold_subtrees<SlotSpan>(
      tree,
      [](const BinaryNode& n) {
        return SlotSpan{n.first, n.first + n.count};
      },
      [](SlotSpan a, SlotSpan b) {
        return SlotSpan{std::min(a.begin, b.begin), std::max(a.end, b.end)};
      });
}

template <int N>
class Collapser {
 public:
  Collapser(const BinaryBvh& tree, CollapseRule rule, const std::vector<SlotSpan>& spans,
            uint32_t merge_slots)
      : tree_(tree), rule_(rule), spans_(spans), merge_slots_(merge_slots) {
    if (rule == CollapseRule::most_triangles) count_triangles();
  }

  std::vector<WideNode<N>> run(uint32_t& depth, uint32_t& leaves, double& sah_cost) {
    nodes_.emplace_back();
    clear(nodes_[0]);
    if (!tree_.nodes.empty()) {
      const BinaryNode& root = tree_.nodes[0];
      if (root.leaf() || mergeable(0)) {
        set_child(0, 0, root.box, root.leaf() ? leaf_ref(root) : merged_leaf_ref(0));
        depth_ = 1;
      } else {
        fill(0, 0, 1);
      }
    } else {
      depth_ = 1;
    }
    depth = depth_;
    leaves = leaves_;
    sah_cost = sah_cost_;
    return std::move(nodes_);
  }

 private:
  static void clear(WideNode<N>& n) {
    const float inf = std::numeric_limits<float>::infinity();
    for (int k = 0; k < N; ++k) {
      for (int a = 0; a < 3; ++a) {
        n.bounds[a][k] = inf;
        n.bounds[a + 3][k] = -inf;
      }
      n.ref[k] = kEmptyRef;
    }
  }

  void set_child(uint32_t w, int k, const BBox& b, uint32_t ref) {
    WideNode<N>& n = nodes_[w];
    for (int a = 0; a < 3; ++a) {
      n.bounds[a][k] = b.lo[a];
      n.bounds[a + 3][k] = b.hi[a];
    }
    n.ref[k] = ref;
  }

  uint32_t leaf_ref(const BinaryNode& leaf) {
    if (leaf.count > kMaxLeafTriangles) throw std::logic_error("BVH leaf larger than 32 triangles");
    ++leaves_;
    return kLeafFlag | (leaf.first << 5) | (leaf.count - 1);
  }

  // Whether inner binary node k becomes one leaf over its slot span (see WideBvh's constructor).
  bool mergeable(uint32_t k) const {
    return merge_slots_ != 0 && spans_[k].end - spans_[k].begin <= merge_slots_;
  }
  uint32_t merged_leaf_ref(uint32_t k) {
    ++leaves_;
    return kLeafFlag | (spans_[k].begin << 5) | (spans_[k].end - spans_[k].begin - 1);
  }

  // triangles_[k]: the triangles under binary node k.
  void count_triangles() {
    triangles_ = fold_subtrees<uint32_t>(
        tree_, [](const BinaryNode& n) { return n.count; }, [](uint32_t a, uint32_t b) { return a + b; });
  }
  // The priority of opening binary node k (see CollapseRule).
  float open_priority(uint32_t k) const {
    if (rule_ == CollapseRule::most_triangles) return float(triangles_[k]);
    return tree_.nodes[k].box.half_area();
  }

  // Fills wide node w from the binary inner node b (at wide level `level`).
  void fill(uint32_t w, uint32_t b, uint32_t level) {
    depth_ = std::max(depth_, level);
    sah_cost_ += tree_.nodes[b].box.half_area();
    uint32_t kids[N];
    int count = 2;
    kids[0] = tree_.nodes[b].first;
    kids[1] = tree_.nodes[b].first + 1;
    while (count < N) {  // open the inner child of the highest priority
      int best = -1;
      float best_priority = -1.0f;
      for (int k = 0; k < count; ++k) {
        if (tree_.nodes[kids[k]].leaf()) continue;
        const float priority = open_priority(kids[k]);
        if (priority > best_priority) {
          best_priority = priority;
          best = k;
        }
      }
      if (best < 0) break;
      const uint32_t opened = kids[best];
      kids[best] = tree_.nodes[opened].first;
      kids[count++] = tree_.nodes[opened].first + 1;
    }
    for (int k = 0; k < count; ++k) {
      const BinaryNode& c = tree_.nodes[kids[k]];
      if (c.leaf()) {
        set_child(w, k, c.box, leaf_ref(c));
      } else if (mergeable(kids[k])) {
        set_child(w, k, c.box, merged_leaf_ref(kids[k]));
      } else {
        const auto child = static_cast<uint32_t>(nodes_.size());
        nodes_.emplace_back();
        clear(nodes_.back());
        set_child(w, k, c.box, child);
        fill(child, kids[k], level + 1);
      }
    }
  }

  const BinaryBvh& tree_;
  const CollapseRule rule_;
  const std::vector<SlotSpan>& spans_;  // empty without merging
  const uint32_t merge_slots_;
  std::vector<uint32_t> triangles_;  // most_triangles only
  std::vector<WideNode<N>> nodes_;
  uint32_t depth_ = 0, leaves_ = 0;
  double sah_cost_ = 0;
};

// The nodes in a LargeBuffer (huge pages for big trees: fewer TLB misses per node fetch).
template <int N>
LargeBuffer collapse(const BinaryBvh& tree, CollapseRule rule, uint32_t merge_slots, uint32_t& count,
                     uint32_t& depth, uint32_t& leaves, double& sah_cost, std::size_t& bytes) {
  const std::vector<SlotSpan> spans = merge_slots != 0 ? subtree_spans(tree) : std::vector<SlotSpan>{};
  std::vector<WideNode<N>> nodes;
  if (rule != CollapseRule::lower_sah_cost) {
    nodes = Collapser<N>(tree, rule, spans, merge_slots).run(depth, leaves, sah_cost);
  } else {
    double by_count = 0;
    uint32_t depth_count = 0, leaves_count = 0;
    std::vector<WideNode<N>> other;
    // the two collapses are independent: one thread each for large trees (4.5 ms each on 1M
    // triangles, ~10 µs on 4k; the 256-node threshold is a round guess, not tuned)
    side_by_side(
        tree.nodes.size() >= kParallelCollapseNodes,
        [&] {
          nodes =
              Collapser<N>(tree, CollapseRule::largest_area, spans, merge_slots).run(depth, leaves, sah_cost);
        },
        [&] {
          other = Collapser<N>(tree, CollapseRule::most_triangles, spans, merge_slots)
                      .run(depth_count, leaves_count, by_count);
        });
    if (by_count < sah_cost) {
      nodes = std::move(other);
      depth = depth_count;
      leaves = leaves_count;
      sah_cost = by_count;
    }
  }
  bytes = nodes.size() * sizeof(WideNode<N>);
  LargeBuffer p = allocate_large_buffer(bytes);
  std::memcpy(p.get(), nodes.data(), bytes);
  count = static_cast<uint32_t>(nodes.size());
  return p;
}

// BvhArrays::root_lo/hi: the union of the root node's child boxes (unused slots are empty boxes).
template <int N>
void root_box(BvhArrays& a) {
  const WideNode<N>& root = static_cast<const WideNode<N>*>(a.nodes)[0];
  for (int axis = 0; axis < 3; ++axis) {
    a.root_lo[axis] = *std::min_element(root.bounds[axis], root.bounds[axis] + N);
    a.root_hi[axis] = *std::max_element(root.bounds[axis + 3], root.bounds[axis + 3] + N);
  }
}

}  // namespace

WideBvh::WideBvh(const BinaryBvh& tree, int width, CollapseRule rule, uint32_t merge_slots) {
  if (tree.order.size() >= kMaxLeafBegin)
    throw std::length_error("BVH: at most 2^26 - 1 triangles are supported");
  if (merge_slots > kMaxLeafTriangles)
    throw std::invalid_argument("BVH: merged leaves hold at most 32 slots");
  uint32_t count = 0;
  LargeBuffer p;
  switch (width) {
    case 4: p = collapse<4>(tree, rule, merge_slots, count, depth_, leaves_, sah_cost_, bytes_); break;
    case 8: p = collapse<8>(tree, rule, merge_slots, count, depth_, leaves_, sah_cost_, bytes_); break;
    case 16: p = collapse<16>(tree, rule, merge_slots, count, depth_, leaves_, sah_cost_, bytes_); break;
    default: throw std::invalid_argument("BVH width must be 4, 8 or 16");
  }
  storage_ = std::move(p);
  arrays_ = BvhArrays{
      storage_.get(), uint32_t(width), count, depth_ * uint32_t(width - 1) + 1, kDefaultBoxEpsilon, {}, {},
      false};
  switch (width) {
    case 4: root_box<4>(arrays_); break;
    case 8: root_box<8>(arrays_); break;
    default: root_box<16>(arrays_); break;
  }
}

namespace {
// A leaf reference's slots [begin, end).
struct LeafSlots {
  uint32_t begin, end;
};
LeafSlots leaf_slots(uint32_t ref) {
  const uint32_t begin = (ref >> 5) & (kMaxLeafBegin - 1);
  return {begin, begin + (ref & 31u) + 1};
}

template <int N>
double tree_sah_cost(const BvhArrays& a, uint32_t step_slots) {
  const auto* nodes = static_cast<const WideNode<N>*>(a.nodes);
  const BBox root_box{{a.root_lo[0], a.root_lo[1], a.root_lo[2]}, {a.root_hi[0], a.root_hi[1], a.root_hi[2]}};
  const float root = root_box.half_area();
  if (a.node_count == 0 || !(root > 0.0f)) return 0.0;
  double cost = 0.0;
  for (uint32_t n = 0; n < a.node_count; ++n) {
    BBox node;
    for (int k = 0; k < N; ++k) {
      const uint32_t ref = nodes[n].ref[k];
      if (ref == kEmptyRef) continue;
      const auto& b = nodes[n].bounds;
      const BBox child{{b[0][k], b[1][k], b[2][k]}, {b[3][k], b[4][k], b[5][k]}};
      node.grow(child);
      if (!(ref & kLeafFlag)) continue;
      const LeafSlots l = leaf_slots(ref);
      cost += double(child.half_area()) * double((l.end - 1) / step_slots - l.begin / step_slots + 1);
    }
    cost += double(node.half_area());
  }
  return cost / double(root);
}

// Leaves' slot ranges are disjoint, so the nodes' leaves sort in parallel; in chunks of nodes, as a
// node's leaves are mostly sorted already (a check of a few slots).
constexpr uint32_t kSortChunkNodes = 256;

template <int N>
void sort_leaves(const BvhArrays& a, std::vector<uint32_t>& order) {
  const auto* nodes = static_cast<const WideNode<N>*>(a.nodes);
#pragma omp parallel for schedule(dynamic, kSortChunkNodes) if (a.node_count > kSortChunkNodes)
  for (uint32_t n = 0; n < a.node_count; ++n)
    for (const uint32_t ref : nodes[n].ref) {
      if (ref == kEmptyRef || !(ref & kLeafFlag)) continue;
      const LeafSlots l = leaf_slots(ref);
      const auto first = order.begin() + l.begin, last = order.begin() + l.end;
      if (!std::is_sorted(first, last)) std::sort(first, last);  // kPaddingSlot is the largest
    }
}
}  // namespace

double WideBvh::sah_cost(uint32_t step_slots) const {
  step_slots = std::max(step_slots, 1u);
  switch (arrays_.width) {
    case 4: return tree_sah_cost<4>(arrays_, step_slots);
    case 8: return tree_sah_cost<8>(arrays_, step_slots);
    default: return tree_sah_cost<16>(arrays_, step_slots);
  }
}

void sort_leaf_slots(const WideBvh& tree, std::vector<uint32_t>& order) {
  switch (tree.width()) {
    case 4: sort_leaves<4>(tree.arrays(), order); break;
    case 8: sort_leaves<8>(tree.arrays(), order); break;
    default: sort_leaves<16>(tree.arrays(), order); break;
  }
}

}  // namespace rayvec
