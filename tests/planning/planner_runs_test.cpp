// Planner runs with fixed seeds on real problems: OMPL.app's Easy and cubicles, and the built-in
// scene.

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/scene/ompl_app_problem.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

struct PlanRun {
  PlannerStatus status;
  PlannerStats stats;
  bool path_valid = false;
};

PlanRun plan(const Problem& problem, const std::string& planner_name, std::uint64_t seed,
             double time_limit) {
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  PlannerSettings settings;
  settings.seed = seed;
  if (auto it = problem.hints.range.find(planner_name); it != problem.hints.range.end())
    settings.range = it->second;
  auto planner = make_planner(planner_name, validator, problem.start, problem.goal, settings);
  Termination t;
  t.time_limit_s = time_limit;
  PlanRun r{planner->solve(t), planner->stats()};
  if (r.status == PlannerStatus::solved) {
    CollisionChecker fresh(problem.scene);
    MotionValidator check(problem.space, fresh);
    r.path_valid = check_path(planner->solution(), check).valid;
  }
  return r;
}

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

TEST(OmplAppRuns, RrtSolvesEasy) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem problem =
      load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" / "Easy.cfg");
  const PlanRun r = plan(problem, "rrt", 1, 60.0);
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
  PlannerSettings settings;
  settings.seed = GetParam();
  settings.extend = *parse_extend_mode(problem.hints.extend.value_or("classic"));
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
