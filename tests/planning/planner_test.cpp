// The planner interface on every planner: solving, determinism, stepping, limits, interruption.

#include "tandem/planning/planner.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <numbers>
#include <thread>

#include "support/problems.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using Fixture = test::ProblemFixture;
using test::closed_problem;

void expect_valid_solution(Fixture& f, const Planner& planner) {
  const Path& path = planner.solution();
  ASSERT_GE(path.size(), 2u);
  EXPECT_TRUE(path.front() == f.problem.start);
  EXPECT_TRUE(path.back() == f.problem.goal);
  const PathCheck check = check_path(path, f.validator);
  EXPECT_TRUE(check.valid) << check.describe();
}

/// Every edge of every tree is a valid motion no longer than the range.
void expect_valid_trees(Fixture& f, const Planner& planner) {
  for (const Tree* tree : planner.trees()) {
    for (std::size_t i = 1; i < tree->size(); ++i) {
      const Config& child = tree->nodes[i];
      const Config& parent = tree->nodes[tree->parent[i]];
      ASSERT_LE(f.problem.space.distance(parent, child), planner.range() * (1 + 1e-9));
      ASSERT_TRUE(f.validator.is_valid(child));
      ASSERT_TRUE(f.validator.check_motion(parent, child));
    }
  }
}

class EveryPlanner : public ::testing::TestWithParam<std::tuple<std::string, ExtendMode>> {};

TEST_P(EveryPlanner, SolvesTheWallWithAGap) {
  Fixture f;
  PlannerSettings settings;
  settings.extend = std::get<1>(GetParam());
  settings.range = 1.0;
  auto planner = f.planner(std::get<0>(GetParam()), settings);
  Termination t;
  t.time_limit_s = 30;
  ASSERT_EQ(planner->solve(t), PlannerStatus::solved);
  EXPECT_EQ(planner->stats().collision_checks, f.validator.checks());
  expect_valid_solution(f, *planner);
  expect_valid_trees(f, *planner);
  const PlannerStats& s = planner->stats();
  std::size_t nodes = 0;
  for (const Tree* tree : planner->trees())
    nodes += tree->size();
  EXPECT_EQ(s.nodes, nodes);
  EXPECT_EQ(s.edges, nodes - planner->trees().size());
  EXPECT_GT(s.iterations, 0u);
}

TEST_P(EveryPlanner, IsDeterministicForASeed) {
  auto run = [&](std::uint64_t seed) {
    Fixture f;
    PlannerSettings settings;
    settings.seed = seed;
    settings.extend = std::get<1>(GetParam());
    settings.range = 1.0;
    auto planner = f.planner(std::get<0>(GetParam()), settings);
    planner->solve(Termination{});
    std::vector<Config> all_nodes;
    for (const Tree* t : planner->trees())
      all_nodes.insert(all_nodes.end(), t->nodes.begin(), t->nodes.end());
    return std::make_tuple(planner->solution(), all_nodes, planner->stats().collision_checks);
  };
  EXPECT_EQ(run(17), run(17));
  EXPECT_NE(std::get<1>(run(17)), std::get<1>(run(18)));
}

INSTANTIATE_TEST_SUITE_P(
    Planners, EveryPlanner,
    ::testing::Combine(::testing::Values("birrt", "rrt"),
                       ::testing::Values(ExtendMode::classic, ExtendMode::last_valid)),
    [](const auto& test_info) {
      return std::get<0>(test_info.param) +
             (std::get<1>(test_info.param) == ExtendMode::classic ? "_classic" : "_last_valid");
    });

TEST(Planner, StepsOneIterationAtATime) {
  Fixture f;
  auto planner = f.planner("birrt");
  EXPECT_EQ(planner->status(), PlannerStatus::running);
  EXPECT_EQ(planner->step(), PlannerStatus::running);
  EXPECT_EQ(planner->stats().iterations, 1u);
  PlannerStatus s = PlannerStatus::running;
  for (int i = 0; i < 100000 && s == PlannerStatus::running; ++i)
    s = planner->step();
  ASSERT_EQ(s, PlannerStatus::solved);
  const auto iterations = planner->stats().iterations;
  EXPECT_EQ(planner->step(), PlannerStatus::solved);
  EXPECT_EQ(planner->stats().iterations, iterations);
}

TEST(Planner, ReportsAnInvalidStartOrGoal) {
  {
    Problem p = test::wall_with_gap_problem();
    p.start.t = {0, 1.5, 0};  // inside the wall
    Fixture f(std::move(p));
    EXPECT_EQ(f.planner("birrt")->solve(Termination{}), PlannerStatus::invalid_start);
  }
  {
    Problem p = test::wall_with_gap_problem();
    p.goal.t = {9, 0, 0};  // outside the bounds
    Fixture f(std::move(p));
    EXPECT_EQ(f.planner("rrt")->solve(Termination{}), PlannerStatus::invalid_goal);
  }
}

TEST(Planner, StopsAtItsLimits) {
  Fixture f(closed_problem());
  auto planner = f.planner("birrt");
  Termination by_iterations;
  by_iterations.max_iterations = 500;
  EXPECT_EQ(planner->solve(by_iterations), PlannerStatus::iteration_limit);
  EXPECT_EQ(planner->stats().iterations, 500u);
  Termination by_time;
  by_time.time_limit_s = planner->stats().time_s + 0.2;
  EXPECT_EQ(planner->solve(by_time), PlannerStatus::timeout);
  EXPECT_GE(planner->stats().time_s, 0.2);
  EXPECT_LT(planner->stats().time_s, 5.0);
  EXPECT_TRUE(planner->solution().empty());
}

TEST(Planner, CanBeInterruptedFromAnotherThread) {
  Fixture f(closed_problem());
  auto planner = f.planner("birrt");
  PlannerStatus result = PlannerStatus::running;
  std::thread worker([&] { result = planner->solve(Termination{}); });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  planner->interrupt();
  worker.join();
  EXPECT_EQ(result, PlannerStatus::interrupted);
  // It can resume afterwards.
  Termination more;
  more.max_iterations = 10;
  EXPECT_EQ(planner->solve(more), PlannerStatus::iteration_limit);
}

}  // namespace
}  // namespace tandem
