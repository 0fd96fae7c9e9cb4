// The C interface of librayvec_embree.so, the module that holds the Embree 3 rival of
// `rayvec bench rays --vs-embree`. Only that command uses Embree, so the binary loads the module (and
// with it Embree and TBB) with dlopen on first use instead of linking them: linked, they cost every
// command about 2 ms and 4 MB at start (docs/benchmarks.md#decision-embree-module). Rays and hits cross
// as rayvec's own plain structs (rays/ray.h: floats and an int, no C++ objects), so the rival traces
// the very arrays rayvec traces, without a copy in the timed loop.
#pragma once
#include <cstddef>
#include <cstdint>

#include "rays/ray.h"

extern "C" {

// Bumped whenever a signature below changes; the loader refuses a module of another version.
constexpr int kRayvecEmbreeAbi = 2;

using RayvecEmbreeAbiFn = int (*)();
// A scene over `vertex_count` vertices (x, y, z) and `triangle_count` vertex-index triples, built with
// RTC_BUILD_QUALITY_HIGH on a device of `threads` threads (0: Embree's default) whose ISA is capped at
// `max_isa` ("sse2", "avx2", "avx512"). *build_seconds receives rtcCommitScene's wall time. Null with
// `error` filled on failure.
using RayvecEmbreeBuildFn = void* (*)(const float* vertices, std::size_t vertex_count,
                                      const uint32_t* triangles, std::size_t triangle_count, int threads,
                                      const char* max_isa, double* build_seconds, char* error,
                                      std::size_t error_size);
// rtcIntersect1 for each of n rays.
using RayvecEmbreeClosestFn = void (*)(void* scene, const rayvec::Ray* rays, rayvec::Hit* hits,
                                       std::size_t n);
// rtcIntersect16 on one coherent packet of n <= 16 rays.
using RayvecEmbreePacketFn = void (*)(void* scene, const rayvec::Ray* rays, rayvec::Hit* hits, std::size_t n);
// rtcOccluded1 for each of n rays: out[i] = 1 when ray i is blocked.
using RayvecEmbreeOccludedFn = void (*)(void* scene, const rayvec::Ray* rays, uint8_t* out, std::size_t n);
// rtcOccluded16 on one coherent packet of n <= 16 rays: out[k] = 1 when ray k is blocked.
using RayvecEmbreeOccludedPacketFn = void (*)(void* scene, const rayvec::Ray* rays, uint8_t* out,
                                              std::size_t n);
using RayvecEmbreeReleaseFn = void (*)(void* scene);
}

namespace rayvec {
inline constexpr const char* kEmbreeModuleName = "librayvec_embree.so";
}
