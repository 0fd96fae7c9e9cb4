// The body of lane_rules_<isa>.cpp: included inside namespace rayvec::<isa> after that ISA's vector
// and packet-lane headers, kernels/moller_trumbore.inl and kernels/mt_float.inl, with PacketFloat
// the packets' lane type (16 lanes), whose next_up and PacketForward are tested.

namespace {
void next_up_lanes(const float* in, float* out, int n) {
  for (int i = 0; i < n; i += PacketFloat::W) next_up(PacketFloat::load(in + i)).store(out + i);
}
void mt_lower_lanes(const float* in, float* out, int n) {
  for (int i = 0; i < n; i += vfloat::W) mt_lower(vfloat::load(in + i)).store(out + i);
}
void packet_hull_lanes(const float* soa, unsigned lanes, float eps, test::PacketHullLanes* out) {
  const float* const rows[8] = {soa, soa + 16, soa + 32, soa + 48, soa + 64, soa + 80, soa + 96, soa + 112};
  const PacketFloat r[3] = {PacketFloat::load(rows[3]), PacketFloat::load(rows[4]),
                            PacketFloat::load(rows[5])};
  unsigned neg[3];
  for (int a = 0; a < 3; ++a) neg[a] = bits(r[a] < PacketFloat::broadcast(0.0f)) & lanes;
  const auto k = PacketForward<PacketFloat, true>::load(rows, neg, eps);
  float tmax = 0.0f;
  const PacketHull h = k.hull(r, lanes, &tmax);
  for (int a = 0; a < 3; ++a) {
    const float bounds[6] = {h.nr_lo[a], h.nr_hi[a], h.fr_lo[a], h.fr_hi[a], h.kn_hi[a], h.kf_lo[a]};
    for (int b = 0; b < 6; ++b) out->hull[3 * b + a] = bounds[b];
  }
  out->hull[18] = h.tmin;
  out->hull[19] = tmax;
  const PacketFloat each[14] = {k.nrx, k.nry, k.nrz, k.frx, k.fry, k.frz,  k.knx,
                                k.kny, k.knz, k.kfx, k.kfy, k.kfz, k.tmin, k.tmax};
  for (int j = 0; j < 14; ++j) each[j].store(out->lanes[j]);
}
void det_sign_forms_lanes(const float* x, const float* det, float slack, float* out, int n) {
  const vfloat c = vfloat::broadcast(slack), zero = vfloat::broadcast(0.0f);
  for (int i = 0; i < n; i += vfloat::W) {
    const vfloat a = vfloat::load(x + i), d = vfloat::load(det + i), s = sign_one(d);
    const vfloat forms[6] = {fnmadd(s, a, c),    c - xor_sign(a, d), fmadd(s, a, c),
                             xor_sign(a, d) + c, fmadd(s, a, zero),  xor_sign(a, d) + zero};
    for (int r = 0; r < 6; ++r) forms[r].store(out + r * n + i);
  }
}
}  // namespace
