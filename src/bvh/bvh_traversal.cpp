// Chooses the BVH traversal table for an ISA and node width. Baseline code; ISA units are entered
// only when the CPU supports them.
#include <stdexcept>
#include <string>

#include "bvh/bvh_traversal.h"

namespace rayvec {

BvhWidths bvh_widths(Isa isa) {
  switch (isa) {
    case Isa::avx512: return {{8, 16, 0}, 2};
    case Isa::avx2: return {{8, 16, 0}, 2};
    case Isa::scalar: break;
  }
  return {{8, 4, 0}, 2};
}

int default_bvh_width(Isa isa, std::size_t triangles, std::string_view vendor) {
  if (isa == Isa::avx512 && vendor == "GenuineIntel") return 16;
  return isa != Isa::scalar && triangles >= kWideNodeTriangles ? 16 : 8;
}

int default_bvh_width(Isa isa, std::size_t triangles) {
  return default_bvh_width(isa, triangles, cpu_features().vendor);
}

int default_leaf_steps(Isa isa, std::size_t triangles) {
  return isa != Isa::scalar && triangles < kWideNodeTriangles ? 1 : 2;
}

const char* leaf_call_name(LeafCall call) {
  switch (call) {
    case LeafCall::direct: return "direct";
    case LeafCall::inlined: return "inlined";
    case LeafCall::table: break;
  }
  return "table";
}

LeafCall default_leaf_call(Isa isa, Intersector intersector, std::size_t triangles) {
  if (isa == Isa::scalar || (intersector != Intersector::mt && intersector != Intersector::watertight))
    return LeafCall::table;
  return triangles >= kWideNodeTriangles ? LeafCall::inlined : LeafCall::direct;
}

const BvhTraversal& bvh_traversal(Isa isa, int width, LeafCall call, Intersector intersector) {
  if (!isa_supported(isa)) throw std::runtime_error(std::string("this CPU cannot run ISA ") + isa_name(isa));
  const BvhTraversal* k = nullptr;
  switch (isa) {
    case Isa::avx512: k = avx512::bvh_traversal(width, call, intersector); break;
    case Isa::avx2: k = avx2::bvh_traversal(width, call, intersector); break;
    case Isa::scalar: k = scalar::bvh_traversal(width, call, intersector); break;
  }
  if (!k)
    throw std::invalid_argument("no " + std::to_string(width) + "-wide BVH traversal for ISA " +
                                isa_name(isa));
  return *k;
}

}  // namespace rayvec
