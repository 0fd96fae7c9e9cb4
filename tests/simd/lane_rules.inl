// The body of lane_rules_<isa>.cpp: included inside namespace rayvec::<isa> after that ISA's vector
// header, kernels/moller_trumbore.inl and kernels/mt_float.inl, with NextUpLanes the type whose
// next_up is tested (the packets' lane type).

namespace {
void next_up_lanes(const float* in, float* out, int n) {
  for (int i = 0; i < n; i += NextUpLanes::W) next_up(NextUpLanes::load(in + i)).store(out + i);
}
void mt_lower_lanes(const float* in, float* out, int n) {
  for (int i = 0; i < n; i += vfloat::W) mt_lower(vfloat::load(in + i)).store(out + i);
}
}  // namespace
