# Runtime ISA dispatch: each ISA's code lives in its own translation units, compiled with that ISA's
# flags (and only those units) through rayvec_add_isa_units. Everything else is baseline x86-64, so
# the one binary runs on any x86-64 CPU and picks its code by cpuid at run time. Never -march=native.
# -ffp-contract=off: g++ contracts a*b+c into FMA by default in C++ (even with -std=c++20), which would
# make the `paper` kernels round differently from the scalar ISA and the paper baselines. FMA is used
# only where a kernel asks for it explicitly (fmadd/fmsub).
set(RAYVEC_AVX2_FLAGS -mavx2 -mfma -mbmi -mbmi2 -mlzcnt -mf16c -mpopcnt -ffp-contract=off)
# -Wno-maybe-uninitialized: g++ 12's own AVX-512 intrinsics (_mm512_min_ps, _mm512_max_ps, ...) pass
# _mm512_undefined_*() as their merge source and trip this warning in every caller (a known false positive).
set(RAYVEC_AVX512_FLAGS ${RAYVEC_AVX2_FLAGS} -mavx512f -mavx512dq -mavx512bw -mavx512vl -mavx512cd
    -Wno-maybe-uninitialized)

# rayvec_add_isa_units(TARGET ISA SOURCE...): compiles the SOURCEs, ISA units of TARGET, with the
# flags of ISA (avx2 or avx512) as the OBJECT library TARGET_ISA, and adds its objects to TARGET.
# The units see what rayvec_common gives (include root src/, warnings) and nothing else.
function(rayvec_add_isa_units target isa)
  string(TOUPPER "${isa}" upper)
  if(NOT DEFINED RAYVEC_${upper}_FLAGS)
    message(FATAL_ERROR "rayvec_add_isa_units: unknown ISA '${isa}'")
  endif()
  add_library(${target}_${isa} OBJECT ${ARGN})
  target_compile_options(${target}_${isa} PRIVATE ${RAYVEC_${upper}_FLAGS})
  target_link_libraries(${target}_${isa} PRIVATE rayvec_common)
  target_sources(${target} PRIVATE $<TARGET_OBJECTS:${target}_${isa}>)
endfunction()
