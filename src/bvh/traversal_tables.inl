// The BvhTraversal tables of a SIMD ISA unit and the choice among them, written once: included by
// bvh_traversal_avx2.cpp and bvh_traversal_avx512.cpp inside their namespace, after the traversals
// and the unit's leaf policies — kThisIsa, PacketLanes16, DirectMtLeaf (the float `mt` kernels
// called directly) and TableAnyHitLeaf (the any-hit leaf of the tables that call the closest-hit
// kernel through the table: the table itself, or where the unit measured it faster, its direct
// any-hit kernel). Per node width: the table's leaves, the direct `mt` leaves, the direct
// `watertight` leaves (bvh/watertight_leaf.inl).

namespace {

template <class B, class ClosestLeaf, class AnyHitLeaf>
constexpr BvhTraversal traversal_table(int width, bool direct_leaf) {
  return {kThisIsa,
          width,
          &bvh_closest<B, ClosestLeaf>,
          &bvh_occluded<B, AnyHitLeaf>,
          &bvh_closest_packet<B, PacketLanes16>,
          &bvh_occluded_packet<B, PacketLanes16, AnyHitLeaf>,
          PacketLanes16::P,
          direct_leaf};
}

// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const BvhTraversal k8 = traversal_table<BoxLanes8, TableLeaf, TableAnyHitLeaf>(8, false);
constinit const BvhTraversal k16 = traversal_table<BoxLanes16, TableLeaf, TableAnyHitLeaf>(16, false);
constinit const BvhTraversal k8_direct = traversal_table<BoxLanes8, DirectMtLeaf, DirectMtLeaf>(8, true);
constinit const BvhTraversal k16_direct = traversal_table<BoxLanes16, DirectMtLeaf, DirectMtLeaf>(16, true);
constinit const BvhTraversal k8_watertight =
    traversal_table<BoxLanes8, WatertightLeaf<vfloat>, WatertightLeaf<vfloat>>(8, true);
constinit const BvhTraversal k16_watertight =
    traversal_table<BoxLanes16, WatertightLeaf<vfloat>, WatertightLeaf<vfloat>>(16, true);
}  // namespace

const BvhTraversal* bvh_traversal(int width, bool direct_leaf, Intersector intersector) {
  const bool mt = direct_leaf && intersector == Intersector::mt;
  const bool watertight = direct_leaf && intersector == Intersector::watertight;
  switch (width) {
    case 8: return mt ? &k8_direct : watertight ? &k8_watertight : &k8;
    case 16: return mt ? &k16_direct : watertight ? &k16_watertight : &k16;
    default: return nullptr;
  }
}
