// side_by_side(): both jobs run, on two threads at once where asked (each waits to see the other
// started), one after the other otherwise; an exception of either is rethrown once both are done.
#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "platform/side_by_side.h"

namespace rayvec {
namespace {

// Marks `mine` and waits up to 10 s for `other`: true when the other job started meanwhile.
bool meet(std::atomic<bool>& mine, const std::atomic<bool>& other) {
  mine = true;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!other && std::chrono::steady_clock::now() < until) std::this_thread::yield();
  return other;
}

TEST(SideBySide, ParallelJobsRunAtTheSameTimeOnTwoThreads) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  std::atomic<bool> a{false}, b{false};
  bool a_met = false, b_met = false;
  int a_thread = -1, b_thread = -1;
  side_by_side(
      true,
      [&] {
        a_thread = omp_get_thread_num();
        a_met = meet(a, b);
      },
      [&] {
        b_thread = omp_get_thread_num();
        b_met = meet(b, a);
      });
  omp_set_num_threads(threads);
  EXPECT_TRUE(a_met && b_met);
  EXPECT_NE(a_thread, b_thread);
}

// `--threads 1` must mean one thread: the limit wins over the request.
TEST(SideBySide, OneThreadAllowedRunsTheJobsInTurnOnTheCallingThread) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  int order = 0, a_at = 0, b_at = 0, team = 0;
  side_by_side(
      true,
      [&] {
        a_at = ++order;
        team = omp_get_num_threads();
      },
      [&] { b_at = ++order; });
  omp_set_num_threads(threads);
  EXPECT_EQ(team, 1);
  EXPECT_EQ(a_at, 1);
  EXPECT_EQ(b_at, 2);
}

TEST(SideBySide, SerialJobsRunOneAfterTheOtherOnTheCallingThread) {
  int order = 0, a_at = 0, b_at = 0;
  side_by_side(
      false, [&] { a_at = ++order; }, [&] { b_at = ++order; });
  EXPECT_EQ(a_at, 1);
  EXPECT_EQ(b_at, 2);
}

TEST(SideBySide, AnExceptionIsRethrownAfterBothJobsFinish) {
  for (bool parallel : {true, false}) {
    bool a_done = false;
    EXPECT_THROW(side_by_side(
                     parallel, [&] { a_done = true; }, [] { throw std::runtime_error("out of memory"); }),
                 std::runtime_error);
    EXPECT_TRUE(a_done) << parallel;
    bool b_done = false;
    EXPECT_THROW(side_by_side(
                     parallel, [] { throw std::invalid_argument("bad"); }, [&] { b_done = true; }),
                 std::invalid_argument);
    EXPECT_TRUE(b_done) << parallel;
  }
}

}  // namespace
}  // namespace rayvec
