// RRT runs with fixed seeds on real problems: OMPL.app's Easy.

#include "tandem/planning/rrt.hpp"

#include <gtest/gtest.h>

#include "support/runs.hpp"
#include "tandem/scene/ompl_app_problem.hpp"

namespace tandem {
namespace {

using test::plan;
using test::PlanRun;

TEST(OmplAppRuns, RrtSolvesEasy) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem problem =
      load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" / "Easy.cfg");
  const PlanRun r = plan(problem, "rrt", 1, 60.0);
  ASSERT_EQ(r.status, PlannerStatus::solved);
  EXPECT_TRUE(r.path_valid);
}

}  // namespace
}  // namespace tandem
