// The body of fma_rates() for one ISA unit (fma_rate_<isa>.cpp), over that unit's vfloat.
// Twelve independent chains a = a·m + c: each FMA depends only on its own chain's previous one,
// so the loop is bound by FMA throughput, not latency (12 chains ≥ 2 pipes × 4 cycles). The
// values stay finite (m < 1 pulls them toward c / (1 − m)), so no slow denormal or inf paths.
void fma_rates(double* rates) {
  constexpr long kIterations = 200'000;  // 2.4 M vector FMAs ≈ 0.3 ms at 2 per cycle
  const vfloat m = vfloat::broadcast(0.999999f), c = vfloat::broadcast(1e-6f);
  float sink = 0;
  for (int round = 0; round < kFmaRounds; ++round) {
    vfloat a0 = vfloat::broadcast(1.0f), a1 = vfloat::broadcast(1.1f), a2 = vfloat::broadcast(1.2f),
           a3 = vfloat::broadcast(1.3f), a4 = vfloat::broadcast(1.4f), a5 = vfloat::broadcast(1.5f),
           a6 = vfloat::broadcast(1.6f), a7 = vfloat::broadcast(1.7f), a8 = vfloat::broadcast(1.8f),
           a9 = vfloat::broadcast(1.9f), a10 = vfloat::broadcast(2.0f), a11 = vfloat::broadcast(2.1f);
    const double start = thread_cpu_seconds();
    for (long i = 0; i < kIterations; ++i) {
      a0 = fmadd(a0, m, c);
      a1 = fmadd(a1, m, c);
      a2 = fmadd(a2, m, c);
      a3 = fmadd(a3, m, c);
      a4 = fmadd(a4, m, c);
      a5 = fmadd(a5, m, c);
      a6 = fmadd(a6, m, c);
      a7 = fmadd(a7, m, c);
      a8 = fmadd(a8, m, c);
      a9 = fmadd(a9, m, c);
      a10 = fmadd(a10, m, c);
      a11 = fmadd(a11, m, c);
    }
    const double seconds = thread_cpu_seconds() - start;
    // the results are used, so the loop cannot be dropped
    const vfloat s = ((a0 + a1) + (a2 + a3)) + ((a4 + a5) + (a6 + a7)) + ((a8 + a9) + (a10 + a11));
    alignas(64) float lanes[vfloat::W];
    s.store(lanes);
    sink += lanes[0];
    rates[round] = seconds > 0 ? double(kIterations) * 12.0 / seconds * 1e-9 : 0.0;
  }
  if (sink == 12345.0f) rates[0] += 1e-9;  // ties sink to the results
}
