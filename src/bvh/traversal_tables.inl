// The BvhTraversal tables of a SIMD ISA unit and the choice among them, written once: included by
// bvh_traversal_avx2.cpp and bvh_traversal_avx512.cpp inside their namespace, after the traversals
// and the unit's leaf policies — kThisIsa, PacketLanes16, DirectMtLeaf and InlinedMtLeaf (the float
// `mt` kernels called directly, out of line or inlined) and TableAnyHitLeaf (the any-hit leaf of
// the tables that call the closest-hit kernel through the table: the table itself, or where the
// unit measured it faster, its direct any-hit kernel). Per node width: the table's leaves, the
// direct `mt` and `watertight` (bvh/watertight_leaf.inl) leaves, called and inlined.

namespace {

template <class B, class ClosestLeaf, class AnyHitLeaf>
constexpr BvhTraversal traversal_table(int width, LeafCall call) {
  return {kThisIsa,
          width,
          &bvh_closest<B, ClosestLeaf>,
          &bvh_occluded<B, AnyHitLeaf>,
          &bvh_closest_packet<B, PacketLanes16>,
          &bvh_occluded_packet<B, PacketLanes16, AnyHitLeaf>,
          PacketLanes16::P,
          call};
}

// One node width's tables.
struct WidthTables {
  BvhTraversal table, mt_direct, mt_inlined, watertight_direct, watertight_inlined;
};

template <class B>
constexpr WidthTables width_tables(int width) {
  return {traversal_table<B, TableLeaf, TableAnyHitLeaf>(width, LeafCall::table),
          traversal_table<B, DirectMtLeaf, DirectMtLeaf>(width, LeafCall::direct),
          traversal_table<B, InlinedMtLeaf, DirectMtLeaf>(width, LeafCall::inlined),
          traversal_table<B, WatertightLeaf<vfloat>, WatertightLeaf<vfloat>>(width, LeafCall::direct),
          traversal_table<B, WatertightLeaf<vfloat, true>, WatertightLeaf<vfloat>>(width, LeafCall::inlined)};
}

// constinit: no dynamic initialisation runs in an ISA unit (it would run on CPUs without the ISA).
constinit const WidthTables k8 = width_tables<BoxLanes8>(8);
constinit const WidthTables k16 = width_tables<BoxLanes16>(16);

const BvhTraversal* pick(const WidthTables& k, LeafCall call, Intersector intersector) {
  if (call == LeafCall::table) return &k.table;
  const bool inlined = call == LeafCall::inlined;
  if (intersector == Intersector::mt) return inlined ? &k.mt_inlined : &k.mt_direct;
  if (intersector == Intersector::watertight) return inlined ? &k.watertight_inlined : &k.watertight_direct;
  return &k.table;
}
}  // namespace

const BvhTraversal* bvh_traversal(int width, LeafCall call, Intersector intersector) {
  switch (width) {
    case 8: return pick(k8, call, intersector);
    case 16: return pick(k16, call, intersector);
    default: return nullptr;
  }
}
