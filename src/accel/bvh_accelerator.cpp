#include "accel/bvh_accelerator.h"

#include <algorithm>
#include <cmath>

#include "bvh/leaf_alignment.h"
#include "geometry/triangle_mesh.h"
#include "platform/side_by_side.h"
#include "platform/stopwatch.h"

namespace rayvec {
namespace {

// Brute force never hits a ray with a NaN or infinite origin or direction, or a NaN interval (every
// kernel comparison is ordered); rejecting them here keeps NaN out of the box test.
bool traceable(const Ray& r) {
  return std::isfinite(r.org.x) && std::isfinite(r.org.y) && std::isfinite(r.org.z) &&
         std::isfinite(r.dir.x) && std::isfinite(r.dir.y) && std::isfinite(r.dir.z) && !std::isnan(r.tmin) &&
         !std::isnan(r.tmax);
}

// How the traversals reach the leaf kernel: BvhOptions::leaf_call, or by default default_leaf_call.
LeafCall leaf_call(const TraceConfig& config, const BvhOptions& options, std::size_t triangles) {
  if (options.leaf_call < 0) return default_leaf_call(config.isa, config.intersector, triangles);
  return LeafCall(options.leaf_call);
}

// A binary SAH tree with its leaves aligned to the kernel's steps, and its wide collapse.
struct BuiltTree {
  BinaryBvh binary;
  WideBvh wide;
  BvhBuildTimes times;  // tree, align and collapse
};

BuiltTree build_tree(const TriangleMesh& mesh, const SahConfig& sah, uint32_t step_slots, int width,
                     uint32_t merge_slots) {
  auto t0 = std::chrono::steady_clock::now();
  BuiltTree t{build_binned_sah(mesh, sah), {}, {}};
  t.times.tree = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  align_leaves(t.binary, step_slots);
  t.times.align = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  t.wide = WideBvh(t.binary, width, CollapseRule::lower_sah_cost, merge_slots);
  t.times.collapse = seconds_since(t0);
  return t;
}

}  // namespace

Normals bvh_normals(Intersector intersector, int stored_normals, std::size_t tree_bytes, std::size_t slots,
                    std::size_t triangles) {
  if (intersector != Intersector::mt || stored_normals == 0) return Normals::formed;
  if (stored_normals > 0) return Normals::stored;
  if (triangles >= kFormedNormalsFrom) return Normals::formed;
  const double bytes = double(tree_bytes) + double(TriangleSoA::bytes_for(uint32_t(slots), Normals::stored));
  return bytes <= kBvhBytesPerTriangle * double(triangles) ? Normals::stored : Normals::formed;
}

BvhAccelerator::BvhAccelerator(const TriangleMesh& mesh, const TraceConfig& config, const BvhOptions& options)
    : config_(config),
      kernels_(&triangle_kernels(config.isa, config.intersector)),
      traversal_(&bvh_traversal(config.isa,
                                options.width ? options.width : default_bvh_width(config.isa, mesh.size()),
                                leaf_call(config, options, mesh.size()), config.intersector)) {
  SahConfig sah = options.sah;
  const uint32_t step = uint32_t(kernels_->width);
  const bool from_kernel = options.leaves_from_kernel && step >= 8;
  if (from_kernel) {
    sah.leaf_block = step;
    const int steps =
        options.leaf_steps > 0 ? options.leaf_steps : default_leaf_steps(config.isa, mesh.size());
    leaf_steps_ = steps;
    sah.max_leaf = std::min(uint32_t(steps) * sah.leaf_block, kMaxLeafTriangles);
  }
  const auto merge_slots = std::min(uint32_t(std::max(options.merge_steps, 0)) * step, kMaxLeafTriangles);
  BuiltTree built;
  // Small meshes: a second tree whose SAH costs leaves in half steps (so it splits where halving a
  // leaf's triangles shrinks its box enough), kept when its whole-tree cost is the lower: long
  // triangles' boxes gain, compact meshes' do not (benchmarks.md#decision-leaf-block-choice).
  if (from_kernel && mesh.size() < kWideNodeTriangles) {
    SahConfig half = sah;
    half.leaf_block = step / 2;
    BuiltTree other;
    // The two trees are independent: with two threads or more, one thread builds each, alone (a
    // small mesh's build is too short for its own parallel parts to pay for their hand-overs;
    // benchmarks.md#decision-build-chunk-sizes).
    side_by_side(
        true, [&] { built = build_tree(mesh, sah, step, traversal_->width, merge_slots); },
        [&] { other = build_tree(mesh, half, step, traversal_->width, merge_slots); });
    if (other.wide.sah_cost(step) < built.wide.sah_cost(step)) {
      built = std::move(other);
      sah = half;
    }
  } else {
    built = build_tree(mesh, sah, step, traversal_->width, merge_slots);
  }
  leaf_block_ = sah.leaf_block;
  BinaryBvh& binary = built.binary;
  tree_ = std::move(built.wide);
  build_times_ = built.times;
  auto t0 = std::chrono::steady_clock::now();
  sort_leaf_slots(tree_, binary.order);
  build_times_.sort = seconds_since(t0);
  tree_.set_box_epsilon(options.box_epsilon);
  tree_.set_packet_slot_cull(options.packet_slot_cull < 0 ? mesh.size() < kPacketSlotCullBelow
                                                          : options.packet_slot_cull != 0);
  t0 = std::chrono::steady_clock::now();
  tris_ = TriangleSoA(mesh, binary.order,
                      bvh_normals(config.intersector, options.stored_normals, tree_.bytes(),
                                  binary.order.size(), mesh.size()));
  build_times_.fill = seconds_since(t0);
}

bool packet_aligned(const Ray* rays, std::size_t n) {
  const Vec3f d0 = rays[0].dir;
  const float c2 = kPacketCone * kPacketCone * dot(d0, d0);
  for (std::size_t k = 1; k < n; ++k) {  // cos >= kPacketCone, squared: no square roots
    const Vec3f d = rays[k].dir;
    const float c = dot(d, d0);
    if (!(c > 0 && c * c >= c2 * dot(d, d))) return false;
  }
  return true;
}

bool packet_coherent(const Ray* rays, std::size_t n) {
  for (std::size_t k = 1; k < n; ++k)
    if (!(rays[k].org == rays[0].org)) return false;
  return packet_aligned(rays, n);
}

Hit BvhAccelerator::closest(const Ray& ray) const {
  Hit hit;
  if (traceable(ray)) traversal_->closest(tree_.arrays(), tris_.arrays(), *kernels_, ray, hit);
  return hit;
}

void BvhAccelerator::closest_stream(const Ray* rays, Hit* hits, std::size_t n) const {
  const int w = traversal_->closest_packet ? traversal_->packet_width : 0;
  std::size_t i = 0;
  for (; w > 0 && i + 1 < n; i += std::size_t(w)) {
    // the packet resets the hits and drops the untraceable lanes itself, in SIMD
    const std::size_t count = std::min(n - i, std::size_t(w));
    traversal_->closest_packet(tree_.arrays(), tris_.arrays(), *kernels_, rays + i, hits + i,
                               (1u << count) - 1u);
  }
  for (; i < n; ++i) hits[i] = closest(rays[i]);
}

void BvhAccelerator::closest_group(const Ray* rays, Hit* hits, std::size_t n) const {
  const std::size_t w = traversal_->closest_packet ? std::size_t(traversal_->packet_width) : 1;
  for (std::size_t i = 0; i < n; i += w) {
    const std::size_t count = std::min(n - i, w);
    if (count > 1 && packet_coherent(rays + i, count))
      closest_stream(rays + i, hits + i, count);
    else
      for (std::size_t k = i; k < i + count; ++k) hits[k] = closest(rays[k]);
  }
}

bool BvhAccelerator::occluded(const Ray& ray, const HitFilter* filter) const {
  return traceable(ray) && traversal_->occluded(tree_.arrays(), tris_.arrays(), *kernels_, ray, filter);
}

void BvhAccelerator::occluded_stream(const Ray* rays, uint8_t* occluded, std::size_t n,
                                     const HitFilter* filters) const {
  const std::size_t w = traversal_->occluded_packet ? std::size_t(traversal_->packet_width) : 1;
  // Occlusion is coherent along a stream: a packet after a mostly occluded one orders its children
  // front to back (benchmarks.md#decision-any-hit-packets).
  bool ordered = false;
  for (std::size_t i = 0; i < n; i += w) {
    const std::size_t count = std::min(n - i, w);
    if (count > 1 && packet_aligned(rays + i, count)) {
      const unsigned hit =
          traversal_->occluded_packet(tree_.arrays(), tris_.arrays(), *kernels_, rays + i, (1u << count) - 1u,
                                      filters ? filters + i : nullptr, ordered);
      for (std::size_t k = 0; k < count; ++k) occluded[i + k] = uint8_t((hit >> k) & 1u);
      ordered = 2 * std::size_t(__builtin_popcount(hit)) > count;
    } else {
      for (std::size_t k = i; k < i + count; ++k)
        occluded[k] = this->occluded(rays[k], filters ? &filters[k] : nullptr);
    }
  }
}

Hit BvhAccelerator::closest_counted(const Ray& ray, TraversalCost& cost) const {
  Hit hit;
  if (traceable(ray)) scalar::counted_closest(tree_.arrays(), tris_.arrays(), *kernels_, ray, hit, cost);
  return hit;
}

bool BvhAccelerator::occluded_counted(const Ray& ray, TraversalCost& cost) const {
  return traceable(ray) &&
         scalar::counted_occluded(tree_.arrays(), tris_.arrays(), *kernels_, ray, nullptr, cost);
}

}  // namespace rayvec
