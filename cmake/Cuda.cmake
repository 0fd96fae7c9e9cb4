# RAYVEC_CUDA: the optional CUDA backend (src/gpu/, docs/gpu.md).
#   AUTO (default) — on when a CUDA compiler is found (nvcc on PATH, $CUDACXX or /usr/local/cuda/bin);
#   ON             — required: configuring fails without nvcc;
#   OFF            — never (scripts/build.sh and scripts/sanitize.sh pass it: the CPU suite must not
#                    depend on nvcc, nor spend CI time compiling device code; scripts/test_cuda.sh
#                    builds the CUDA configuration).
# Sets RAYVEC_CUDA_ENABLED and defines rayvec_cuda_target(TARGET) for a target with .cu sources.
set(RAYVEC_CUDA AUTO CACHE STRING "Build the CUDA backend: AUTO (when nvcc is found), ON or OFF")
set_property(CACHE RAYVEC_CUDA PROPERTY STRINGS AUTO ON OFF)
# Real code for data-centre and desktop GPUs of CUDA 13 (which dropped everything below sm_75):
# A100 (80), RTX 30 (86), RTX 40 / L4 / L40 (89), H100 / H200 (90), B200 (100), RTX 50 (120),
# plus PTX of the newest for the driver to compile on later GPUs.
set(RAYVEC_CUDA_ARCHITECTURES "80-real;86-real;89-real;90-real;100-real;120"
    CACHE STRING "CUDA architectures of the device code (CMAKE_CUDA_ARCHITECTURES syntax)")

set(RAYVEC_CUDA_ENABLED OFF)
string(TOUPPER "${RAYVEC_CUDA}" _rayvec_cuda)
if(NOT _rayvec_cuda STREQUAL "OFF")
  if(NOT CMAKE_CUDA_COMPILER AND NOT DEFINED ENV{CUDACXX})
    find_program(RAYVEC_NVCC nvcc PATHS /usr/local/cuda/bin NO_CACHE)
    if(RAYVEC_NVCC)
      set(CMAKE_CUDA_COMPILER "${RAYVEC_NVCC}")
    endif()
  endif()
  include(CheckLanguage)
  check_language(CUDA)
  if(CMAKE_CUDA_COMPILER)
    set(CMAKE_CUDA_ARCHITECTURES "${RAYVEC_CUDA_ARCHITECTURES}")
    set(CMAKE_CUDA_HOST_COMPILER "${CMAKE_CXX_COMPILER}" CACHE FILEPATH "host compiler of nvcc")
    enable_language(CUDA)
    # CMake 3.25 knows no C++20 flag for nvcc (nvcc 12+ has it): the .cu files are C++20 as the rest
    if(NOT CMAKE_CUDA20_STANDARD_COMPILE_OPTION)
      set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION "-std=c++20")
      set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION "-std=c++20")
    endif()
    set(CMAKE_CUDA_STANDARD 20)
    set(CMAKE_CUDA_STANDARD_REQUIRED ON)
    set(RAYVEC_CUDA_ENABLED ON)
    message(STATUS "rayvec: CUDA ${CMAKE_CUDA_COMPILER_VERSION} backend on (${RAYVEC_CUDA_ARCHITECTURES})")
  elseif(_rayvec_cuda STREQUAL "ON")
    message(FATAL_ERROR "RAYVEC_CUDA=ON but no CUDA compiler was found (put nvcc on PATH or set CUDACXX)")
  else()
    message(STATUS "rayvec: no CUDA compiler found, CUDA backend off")
  endif()
endif()

function(rayvec_cuda_target target)
  # the static runtime: no libcudart.so to find at start-up; the runtime initialises on first use
  set_target_properties(${target} PROPERTIES CUDA_RUNTIME_LIBRARY Static)
  # --fmad=false: `a * b + c` rounds twice as on the host; fused steps are explicit (gpu/device_math.h)
  target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CUDA>:--fmad=false -Xcompiler=-Wall,-Wextra>)
  string(REPLACE ";" " " archs "${RAYVEC_CUDA_ARCHITECTURES}")
  target_compile_definitions(${target} PRIVATE
    RAYVEC_CUDA_TOOLKIT="${CMAKE_CUDA_COMPILER_VERSION}" RAYVEC_CUDA_ARCHS="${archs}")
endfunction()
