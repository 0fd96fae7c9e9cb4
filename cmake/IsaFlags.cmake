# Runtime ISA dispatch: each ISA's code lives in files named *_avx2.cpp or *_avx512.cpp, compiled
# with that ISA's flags (and only those files). Everything else is baseline x86-64, so the one binary
# runs on any x86-64 CPU and picks its kernels by cpuid at run time. Never -march=native here.
# -ffp-contract=off: g++ contracts a*b+c into FMA by default in C++ (even with -std=c++20), which would
# make the `paper` kernels round differently from the scalar ISA and the paper baselines. FMA is used
# only where a kernel asks for it explicitly (fmadd/fmsub).
set(RAYVEC_AVX2_FLAGS -mavx2 -mfma -mbmi -mbmi2 -mlzcnt -mf16c -mpopcnt -ffp-contract=off)
# -Wno-maybe-uninitialized: g++ 12's own AVX-512 intrinsics (_mm512_min_ps, _mm512_max_ps, ...) pass
# _mm512_undefined_*() as their merge source and trip this warning in every caller (a known false positive).
set(RAYVEC_AVX512_FLAGS ${RAYVEC_AVX2_FLAGS} -mavx512f -mavx512dq -mavx512bw -mavx512vl -mavx512cd
    -Wno-maybe-uninitialized)

function(rayvec_apply_isa_flags sources_var)
  foreach(src IN LISTS ${sources_var})
    if(src MATCHES "_avx512\\.cpp$")
      set_source_files_properties(${src} PROPERTIES COMPILE_OPTIONS "${RAYVEC_AVX512_FLAGS}")
    elseif(src MATCHES "_avx2\\.cpp$")
      set_source_files_properties(${src} PROPERTIES COMPILE_OPTIONS "${RAYVEC_AVX2_FLAGS}")
    endif()
  endforeach()
endfunction()
