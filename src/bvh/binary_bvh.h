// BinaryBvh and its builder, build_binned_sah: a top-down binary BVH over a triangle mesh by the
// surface area heuristic (MacDonald & Booth 1990), evaluated on centroid bins as in Wald (2007) "On
// fast Construction of SAH-based Bounding Volume Hierarchies". Subtrees are built in parallel with
// OpenMP tasks.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/bbox.h"

namespace rayvec {

struct TriangleMesh;

// A node of the binary build tree. Inner nodes have count == 0 and children `first` and `first + 1`;
// leaves hold triangles [first, first + count) of the builder's triangle order.
struct BinaryNode {
  BBox box;
  uint32_t first = 0;
  uint32_t count = 0;
  bool leaf() const { return count != 0; }
};

struct SahConfig {
  uint32_t max_leaf = 8;        // a range larger than this is always split
  uint32_t leaf_block = 4;      // leaf cost = ceil(n / leaf_block): SIMD kernels test blocks of triangles
  float traversal_cost = 1.0f;  // cost of one node visit, in units of one leaf block
  int bins = 32;
  uint32_t task_threshold = 512;  // ranges at least this large are built as OpenMP tasks
  int max_sah_depth = 64;         // deeper than this, object-median splits (bounds the tree depth)
  // Spatial splits (bvh/spatial_split.h) may add up to this fraction of the triangle count as extra
  // references (triangles in more than one leaf); 0: object splits only. None are tried when the
  // mesh's box is infinite (a vertex at infinity).
  // benchmarks.md#decision-spatial-splits
  float split_budget = 0.3f;
};

struct BinaryBvh {
  // nodes[0] is the root (absent for an empty mesh); children of an inner node are adjacent.
  std::vector<BinaryNode> nodes;
  // Triangle ids in leaf order: leaf [first, first + count) holds order[first .. first + count);
  // inside each leaf the ids increase (the kernels' tie rule needs it). With spatial splits a
  // triangle may be in more than one leaf (SahConfig::split_budget); otherwise in exactly one.
  std::vector<uint32_t> order;
};

// Builds with the calling thread's OpenMP team size (omp_get_max_threads()). Triangles with
// non-finite vertices are kept (they can never be hit) and binned as if their centroid were at the
// low corner of the range. Deterministic: the same mesh and config give the same tree (up to the
// numbering of nodes) for any number of threads.
BinaryBvh build_binned_sah(const TriangleMesh& mesh, const SahConfig& config = {});

}  // namespace rayvec
