// side_by_side(): two independent jobs, each on a thread of its own where `parallel` is true and
// the thread limit (omp_set_num_threads, OMP_NUM_THREADS, `--threads`) allows two (an OpenMP region
// of two sections; a region nested in another gets one thread unless OMP_MAX_ACTIVE_LEVELS asks for
// more), one after the other on the calling thread otherwise. An exception thrown by either job is
// rethrown once both have finished: none may leave an OpenMP section.
#pragma once
#include <omp.h>

#include <exception>

namespace rayvec {

template <class A, class B>
void side_by_side(bool parallel, A&& a, B&& b) {
  std::exception_ptr failed[2];
#pragma omp parallel sections num_threads(2) if (parallel && omp_get_max_threads() > 1)
  {
#pragma omp section
    try {
      a();
    } catch (...) {
      failed[0] = std::current_exception();
    }
#pragma omp section
    try {
      b();
    } catch (...) {
      failed[1] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace rayvec
