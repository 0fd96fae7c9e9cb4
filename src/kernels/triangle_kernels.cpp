// Chooses the kernel table for an ISA. Baseline code; the ISA units are only entered when the CPU
// supports them (checked here, so a wrong --isa is an error and never an illegal instruction).
#include <stdexcept>
#include <string>

#include "kernels/triangle_kernels.h"

namespace rayvec {

MtPretest default_mt_pretest(Isa isa, std::string_view vendor) {
  // Measured on each vendor: the chained compares take fewer instructions and win on Intel's
  // AVX-512; on AMD's Zen 5 every mask write shares the two FMA pipes, so one mask instruction wins
  // there. AVX2 keeps sign_bits everywhere: without mask registers its compares are vector ops too.
  return isa == Isa::avx512 && vendor == "GenuineIntel" ? MtPretest::ordered_compares : MtPretest::sign_bits;
}

const char* mt_pretest_name(MtPretest pretest) {
  return pretest == MtPretest::ordered_compares ? "ordered compares" : "sign bits";
}

namespace {
std::optional<MtPretest> g_chosen_pretest;
}  // namespace

void set_mt_pretest(std::optional<MtPretest> pretest) { g_chosen_pretest = pretest; }

MtPretest mt_pretest_in_use(Isa isa) {
  return g_chosen_pretest ? *g_chosen_pretest : default_mt_pretest(isa, cpu_features().vendor);
}

const TriangleKernels& triangle_kernels(Isa isa, Intersector intersector) {
  return triangle_kernels(isa, intersector, mt_pretest_in_use(isa));
}

const TriangleKernels& triangle_kernels(Isa isa, Intersector intersector, MtPretest pretest) {
  if (!isa_supported(isa)) throw std::runtime_error(std::string("this CPU cannot run ISA ") + isa_name(isa));
  switch (isa) {
    case Isa::avx512: return avx512::triangle_kernels(intersector, pretest);
    case Isa::avx2: return avx2::triangle_kernels(intersector, pretest);
    case Isa::scalar: break;
  }
  return scalar::triangle_kernels(intersector, pretest);
}

}  // namespace rayvec
