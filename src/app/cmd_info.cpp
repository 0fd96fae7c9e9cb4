// `rayvec info`: what this CPU offers, which ISA rayvec picks and what it chooses for it (kernel
// pre-test, BVH shape, where the normals live), threads, library versions, CUDA.
#include <omp.h>

#include <cstdio>
#include <string_view>

#include "accel/bvh_accelerator.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "app/device_option.h"
#include "platform/isa.h"
#include "kernels/triangle_kernels.h"
#include "bvh/binary_bvh.h"
#include "bvh/bvh_traversal.h"
#include "io/text_file.h"

namespace rayvec {
namespace {

// The BVH shape `rayvec` builds by default with `isa` on a CPU of `vendor`, below and from the size
// at which the defaults change (bvh_traversal.h), so a benchmark row can be traced to its tree.
void print_bvh_defaults(Isa isa, std::string_view vendor) {
  const std::size_t small = kWideNodeTriangles - 1, large = kWideNodeTriangles;
  if (isa == Isa::scalar) {  // leaves sized by the builder's defaults, not by a kernel step
    std::printf("          bvh: %d-wide nodes, leaves of up to %u triangles\n",
                default_bvh_width(isa, small, vendor), SahConfig{}.max_leaf);
    return;
  }
  std::printf(
      "          bvh: %d-wide nodes and %d-step leaves below %zu triangles (costed per step or per half "
      "step, whichever tree costs less), %d-wide and %d-step from there\n",
      default_bvh_width(isa, small, vendor), default_leaf_steps(isa, small), large,
      default_bvh_width(isa, large, vendor), default_leaf_steps(isa, large));
}

}  // namespace

void register_info_command(CommandLine& cli) {
  cli.command("info", "Show CPU features, the ISA rayvec picks and its defaults, threads, versions")
      .reads_no_input()
      .run([] {
        const CpuFeatures& f = cpu_features();
        std::printf("rayvec %s\n", RAYVEC_VERSION);
        std::printf("cpu: %s (%s)\n", f.brand.c_str(), f.vendor.c_str());
        std::printf(
            "cpu features: sse2=%d avx=%d avx2=%d fma=%d bmi2=%d avx512f=%d avx512dq=%d "
            "avx512bw=%d avx512vl=%d avx512cd=%d\n",
            f.sse2, f.avx, f.avx2, f.fma, f.bmi2, f.avx512f, f.avx512dq, f.avx512bw, f.avx512vl, f.avx512cd);
        std::printf("os saves: ymm=%d zmm=%d\n", f.os_ymm, f.os_zmm);
        std::printf("isa: %s (auto)\n", isa_name(best_isa()));
        for (Isa isa : kAllIsas) {
          const bool ok = isa_supported(isa);
          std::printf("  %-7s %s", isa_name(isa), ok ? "supported" : "not supported");
          if (ok)
            std::printf(", %d floats per step, mt pre-test: %s", triangle_kernels(isa, Intersector::mt).width,
                        mt_pretest_name(default_mt_pretest(isa, f.vendor)));
          std::printf("\n");
          if (ok) print_bvh_defaults(isa, f.vendor);
        }
        std::printf(
            "bvh normals (mt): stored below %zu triangles while the tree fits %.0f bytes a triangle, "
            "else formed per step\n",
            kFormedNormalsFrom, kBvhBytesPerTriangle);
        const std::size_t large = kWideNodeTriangles;
        std::printf(
            "bvh leaf kernel (mt, watertight on avx2 and avx512): %s below %zu triangles, %s from there\n",
            leaf_call_name(default_leaf_call(Isa::avx2, Intersector::mt, large - 1)), large,
            leaf_call_name(default_leaf_call(Isa::avx2, Intersector::mt, large)));
        std::printf("threads: %d (OpenMP, %d cores)\n", omp_get_max_threads(), omp_get_num_procs());
        if (const auto problem = input_limit_problem())
          std::printf("input limit: %zu MB; %s, so every command that reads input refuses to start\n",
                      max_input_bytes() / 1000000, problem->c_str());
        else
          std::printf("input limit: %zu MB (%s)\n", max_input_bytes() / 1000000,
                      input_limit_from_environment() ? "RAYVEC_MAX_INPUT_MB"
                                                     : "the default; RAYVEC_MAX_INPUT_MB sets it");
        std::printf("compiler: g++ %s, OpenMP %d\n", __VERSION__, _OPENMP);
        print_cuda_info();
        return 0;
      });
}

}  // namespace rayvec
