// The project's function attributes, defined once.
// RAYVEC_INLINE forces inlining of the one-intrinsic lane operations of the SIMD layer and the BVH
// box tests: left out of line in a hot loop, a wrapper such as vfloat::operator+ costs a call per
// operation, and an out-of-line copy compiled with one ISA's flags could be shared with another unit.
// RAYVEC_COLD keeps rare fallbacks (the watertight kernel's double refinement) out of the hot path.
#pragma once

#define RAYVEC_INLINE inline __attribute__((always_inline))
#define RAYVEC_COLD __attribute__((noinline, cold))
