// RRT-Connect (BiRRT) runs with fixed seeds on real problems: OMPL.app's Easy and cubicles, and the
// built-in scene.

#include "tandem/planning/rrt_connect.hpp"

#include <gtest/gtest.h>

#include "support/runs.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/ompl_app_problem.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

using test::plan;
using test::PlanRun;

class OmplAppRuns
    : public ::testing::TestWithParam<std::tuple<std::string, std::string, std::uint64_t>> {};

TEST_P(OmplAppRuns, SolveWithAValidPath) {
  TANDEM_REQUIRE_SHARED_DATA();
  const auto& [name, planner, seed] = GetParam();
  const Problem problem =
      load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" / (name + ".cfg"));
  const PlanRun r = plan(problem, planner, seed, 60.0);
  ASSERT_EQ(r.status, PlannerStatus::solved) << name << " seed " << seed;
  EXPECT_TRUE(r.path_valid);
  EXPECT_GT(r.stats.collision_checks, 0u);
}

INSTANTIATE_TEST_SUITE_P(EasyAndCubicles, OmplAppRuns,
                         ::testing::Combine(::testing::Values("Easy", "cubicles"),
                                            ::testing::Values("birrt"),
                                            ::testing::Values(1, 2, 3, 4, 5)),
                         [](const auto& test_info) {
                           return std::get<0>(test_info.param) + "_" +
                                  std::get<1>(test_info.param) + "_seed" +
                                  std::to_string(std::get<2>(test_info.param));
                         });

TEST(BugtrapRuns, PassageIslandsCarryBiRRTThroughTheFunnel) {
  // Without passage islands no run of tandem (10 of 60 s) or of OMPL got through bugtrap's funnel;
  // with them, BiRRT on one thread does, and its path is valid along every motion.
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem problem =
      load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" / "bugtrap.cfg");
  const PlanRun r = plan(problem, "birrt", 1, 60.0);
  ASSERT_EQ(r.status, PlannerStatus::solved);
  EXPECT_TRUE(r.path_valid);
}

class BuiltinSceneRuns : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(BuiltinSceneRuns, SolveClutteredEnvironment1WithTheScenesSettings) {
  // BiRRT with the scene's own settings (last-valid extension, the default range), as `tandem plan`
  // runs it.
  const Problem problem = load_problem("cluttered-1");
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  PlannerSettings settings = default_spec("birrt", problem.hints).settings;
  settings.seed = GetParam();
  ASSERT_EQ(settings.extend, ExtendMode::last_valid);
  auto planner = make_planner("birrt", validator, problem.start, problem.goal, settings);
  Termination t;
  t.time_limit_s = 120.0;
  ASSERT_EQ(planner->solve(t), PlannerStatus::solved);
  CollisionChecker fresh(problem.scene);
  MotionValidator check(problem.space, fresh);
  EXPECT_TRUE(check_path(planner->solution(), check).valid);
}

INSTANTIATE_TEST_SUITE_P(FirstSeeds, BuiltinSceneRuns, ::testing::Values(1, 2, 3));

TEST(BuiltinSceneGrowth, GrowsTheSameValidTreesForASeed) {
  const Problem problem = load_problem("cluttered-1");
  auto grow = [&](std::uint64_t seed) {
    CollisionChecker checker(problem.scene);
    MotionValidator validator(problem.space, checker);
    PlannerSettings settings;
    settings.seed = seed;
    auto planner = make_planner("birrt", validator, problem.start, problem.goal, settings);
    Termination t;
    t.max_iterations = 3000;
    EXPECT_EQ(planner->solve(t), PlannerStatus::iteration_limit);
    std::vector<Config> nodes;
    for (const Tree* tree : planner->trees()) {
      for (std::size_t i = 1; i < tree->size(); ++i) {
        EXPECT_TRUE(validator.check_motion(tree->nodes[tree->parent[i]], tree->nodes[i]));
      }
      nodes.insert(nodes.end(), tree->nodes.begin(), tree->nodes.end());
    }
    return nodes;
  };
  const auto a = grow(5);
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, grow(5));
}

}  // namespace
}  // namespace tandem
