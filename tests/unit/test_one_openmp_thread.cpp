// OneOpenMpThread: OpenMP regions its thread starts run on that thread alone, even with a
// num_threads clause (as CHOLMOD's have); other threads keep their teams, and the limit is given
// back when it ends. This file is compiled with OpenMP (tests/unit/CMakeLists.txt).
#include <gtest/gtest.h>

#include <thread>

#include "core/one_openmp_thread.h"

namespace lowstretch {
namespace {

int team_of_four() {
  int size = 0;
#pragma omp parallel num_threads(4)
  {
#pragma omp single
    size = omp_get_num_threads();
  }
  return size;
}

TEST(OneOpenMpThread, OnlyItsOwnThreadRunsRegionsAlone) {
  const int levels = omp_get_max_active_levels();
  ASSERT_GE(levels, 1);
  ASSERT_EQ(team_of_four(), 4);
  {
    const OneOpenMpThread alone;
    EXPECT_EQ(team_of_four(), 1);
    int other_team = 0;
    std::thread other([&] { other_team = team_of_four(); });
    other.join();
    EXPECT_EQ(other_team, 4);
    {
      const OneOpenMpThread nested;
      EXPECT_EQ(team_of_four(), 1);
    }
    EXPECT_EQ(team_of_four(), 1);
  }
  EXPECT_EQ(omp_get_max_active_levels(), levels);
  EXPECT_EQ(team_of_four(), 4);
}

}  // namespace
}  // namespace lowstretch
