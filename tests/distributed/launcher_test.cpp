// The launcher is read from the environment alone, so a plain run never loads MPI.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <string>

#include "distributed/launcher.h"
#include "test_support.h"

namespace rayvec {
namespace {

Launch launch_with(const std::map<std::string, std::string>& env) {
  return detect_launch([&](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

TEST(Launcher, PlainProcessIsNotLaunched) {
  const Launch l = launch_with({{"PATH", "/usr/bin"}, {"SLURM_PROCID", "0"}});
  EXPECT_FALSE(l.launched);
  EXPECT_TRUE(l.problem.empty());
}

TEST(Launcher, EachLauncherIsRecognisedWithItsJobSize) {
  EXPECT_EQ(launch_with({{"OMPI_COMM_WORLD_SIZE", "4"}}).ranks, 4);
  EXPECT_EQ(launch_with({{"PMI_RANK", "1"}, {"PMI_SIZE", "3"}}).ranks, 3);
  const Launch srun = launch_with({{"PMIX_RANK", "0"}, {"SLURM_STEP_NUM_TASKS", "8"}});
  EXPECT_TRUE(srun.launched);
  EXPECT_EQ(srun.variable, "PMIX_RANK");
  EXPECT_EQ(srun.ranks, 8);
}

TEST(Launcher, SrunWithoutAnMpiPluginIsAProblemNotALaunch) {
  const Launch l = launch_with({{"SLURM_STEP_NUM_TASKS", "2"}, {"SLURM_STEP_ID", "0"}});
  EXPECT_FALSE(l.launched);
  EXPECT_NE(l.problem.find("srun --mpi=pmix"), std::string::npos) << l.problem;
  EXPECT_TRUE(launch_with({{"SLURM_STEP_NUM_TASKS", "1"}, {"SLURM_STEP_ID", "0"}}).problem.empty());
}

// A launch of several ranks that this build cannot serve fails before any work, exit 2; a launch of
// one rank runs as a plain process.
TEST(Launcher, SeveralRanksWithoutTheMpiModuleIsAnError) {
  ::setenv("RAYVEC_MPI_MODULE", "/nonexistent/librayvec_mpi.so", 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  const auto two = test::run_cli("info");
  ::setenv("OMPI_COMM_WORLD_SIZE", "1", 1);
  const auto one = test::run_cli("info");
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::setenv("SLURM_STEP_NUM_TASKS", "2", 1);
  ::setenv("SLURM_STEP_ID", "0", 1);
  const auto srun = test::run_cli("info");
  ::unsetenv("SLURM_STEP_NUM_TASKS");
  ::unsetenv("SLURM_STEP_ID");
  ::unsetenv("RAYVEC_MPI_MODULE");
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("launched as one of 2 ranks"), std::string::npos) << two.err;
  EXPECT_NE(two.err.find("-DRAYVEC_MPI=ON"), std::string::npos) << two.err;
  EXPECT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(srun.status, 2);
  EXPECT_NE(srun.err.find("srun started 2 tasks without an MPI plugin"), std::string::npos) << srun.err;
}

}  // namespace
}  // namespace rayvec
