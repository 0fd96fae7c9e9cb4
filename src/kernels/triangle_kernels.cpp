// Chooses the kernel table for an ISA. Baseline code; the ISA units are only entered when the CPU
// supports them (checked here, so a wrong --isa is an error and never an illegal instruction).
#include <stdexcept>
#include <string>

#include "kernels/triangle_kernels.h"

namespace rayvec {

const TriangleKernels& triangle_kernels(Isa isa, Intersector intersector) {
  if (!isa_supported(isa)) throw std::runtime_error(std::string("this CPU cannot run ISA ") + isa_name(isa));
  switch (isa) {
    case Isa::avx512: return avx512::triangle_kernels(intersector);
    case Isa::avx2: return avx2::triangle_kernels(intersector);
    case Isa::scalar: break;
  }
  return scalar::triangle_kernels(intersector);
}

}  // namespace rayvec
