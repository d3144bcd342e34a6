// The conformance suite every planner of the registry passes (Drake's way: one suite, every
// implementation): determinism for a seed, the status values, step and interrupt, solutions valid
// under check_path, consistent statistics, and the registry's refusals. A new registry entry is
// picked up here without any edit.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cctype>
#include <memory>
#include <thread>

#include "support/problems.hpp"
#include "support/test_support.hpp"
#include "tandem/interaction/interaction.hpp"
#include "tandem/interaction/operator_feed.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

/// The detour problem with its gap closed (unsolvable), guide kept.
Problem closed_with_guide() {
  Problem p = test::detour_problem();
  p.scene.obstacles.push_back(test::box_body("plug", {0.1, 0.8, 2.0}, {0, 0, 0}));
  return p;
}

/// A registered planner on a problem, with a simulated operator along the problem's guide when
/// the planner takes one.
class Harness : public test::ProblemFixture {
 public:
  Harness(const std::string& name, Problem p, std::uint64_t seed) : ProblemFixture(std::move(p)) {
    RunSpec spec = default_spec(name, problem.hints);
    spec.settings.seed = seed;
    spec.operator_seed = seed;
    if (uses_operator(spec)) {
      feed_ = std::make_unique<VirtualTimeFeed>(
          OperatorModel(checker, make_operator(problem, spec)), spec.operator_period);
      interaction_.feed = feed_.get();
    }
    planner_ = make_planner(name, validator, problem.start, problem.goal, spec.settings,
                            feed_ ? &interaction_ : nullptr);
  }
  Planner& planner() { return *planner_; }

 private:
  std::unique_ptr<VirtualTimeFeed> feed_;
  Interaction interaction_;
  std::unique_ptr<Planner> planner_;
};

class Conformance : public ::testing::TestWithParam<std::string> {};

TEST_P(Conformance, SameSeedSameTreeOtherSeedOtherTree) {
  auto digest = [&](std::uint64_t seed) {
    Harness h(GetParam(), test::detour_problem(), seed);
    for (int i = 0; i < 300 && h.planner().step() == PlannerStatus::running; ++i) {
    }
    return tree_digest(h.planner().trees());
  };
  EXPECT_EQ(digest(4), digest(4));
  EXPECT_NE(digest(4), digest(5));
}

TEST_P(Conformance, SolvesWithAPathValidAlongEveryMotion) {
  Harness h(GetParam(), test::detour_problem(), 1);
  Termination t;
  t.max_iterations = 200000;
  ASSERT_EQ(h.planner().solve(t), PlannerStatus::solved);
  EXPECT_EQ(h.planner().status(), PlannerStatus::solved);
  const std::vector<Config>& path = h.planner().solution();
  ASSERT_GE(path.size(), 2u);
  EXPECT_EQ(path.front(), h.problem.start);
  EXPECT_EQ(path.back(), h.problem.goal);
  CollisionChecker fresh(h.problem.scene);
  MotionValidator check(h.problem.space, fresh);
  EXPECT_TRUE(check_path(path, check).valid) << check_path(path, check).describe();
}

TEST_P(Conformance, StatisticsAgreeWithTheTrees) {
  Harness h(GetParam(), test::detour_problem(), 2);
  std::uint64_t steps = 0;
  while (steps < 400 && h.planner().step() == PlannerStatus::running)
    ++steps;
  const PlannerStats& s = h.planner().stats();
  std::size_t nodes = 0, roots = 0;
  std::array<std::size_t, kNodeSources> by_source{};
  for (const Tree* tree : h.planner().trees()) {
    nodes += tree->size();
    for (std::size_t i = 0; i < tree->size(); ++i) {
      ++by_source[static_cast<std::size_t>(tree->source[i])];
      if (tree->parent[i] == Tree::kNoParent) {
        ++roots;
        continue;
      }
      EXPECT_TRUE(h.validator.check_motion(tree->nodes[tree->parent[i]], tree->nodes[i]));
    }
  }
  EXPECT_EQ(s.nodes, nodes);
  EXPECT_EQ(s.edges, nodes - roots);
  EXPECT_EQ(s.nodes_by_source, by_source);
  EXPECT_EQ(s.nodes_by_source[0], h.planner().trees().size());
  EXPECT_GT(s.collision_checks, 0u);
  EXPECT_EQ(s.iterations, h.planner().status() == PlannerStatus::running ? steps : steps + 1);
  EXPECT_EQ(s.extensions_collision + s.extensions_reached + s.extensions_obstacle > 0, true);
  const bool takes_operator = find_planner(GetParam())->uses_operator;
  EXPECT_EQ(s.operator_iterations > 0, takes_operator);
  if (!takes_operator) {
    EXPECT_EQ(s.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)], 0u);
    EXPECT_EQ(s.nodes_by_source[static_cast<std::size_t>(NodeSource::contact)], 0u);
  }
}

TEST_P(Conformance, LimitsAndInterruptEndSolveWithTheirStatus) {
  {
    Harness h(GetParam(), closed_with_guide(), 1);
    Termination t;
    t.max_iterations = 50;
    EXPECT_EQ(h.planner().solve(t), PlannerStatus::iteration_limit);
    EXPECT_EQ(h.planner().stats().iterations, 50u);
    // solve() may be called again and goes on from where it stopped.
    EXPECT_EQ(h.planner().solve(t), PlannerStatus::iteration_limit);
    EXPECT_EQ(h.planner().stats().iterations, 100u);
    EXPECT_EQ(h.planner().status(), PlannerStatus::running);
  }
  {
    Harness h(GetParam(), closed_with_guide(), 1);
    Termination t;
    t.time_limit_s = 0.05;
    EXPECT_EQ(h.planner().solve(t), PlannerStatus::timeout);
    EXPECT_GE(h.planner().stats().time_s, 0.05);
  }
  {
    Harness h(GetParam(), closed_with_guide(), 1);
    std::thread stopper([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      h.planner().interrupt();
    });
    EXPECT_EQ(h.planner().solve({}), PlannerStatus::interrupted);
    stopper.join();
  }
  {
    Harness h(GetParam(), closed_with_guide(), 1);
    std::atomic<bool> stop{true};
    Termination t;
    t.stop = &stop;
    EXPECT_EQ(h.planner().solve(t), PlannerStatus::interrupted);
  }
}

TEST_P(Conformance, InvalidEndpointsAreStatusesAndStepDoesNothingAfterTheEnd) {
  Problem start_in_wall = test::detour_problem();
  start_in_wall.start.t = {0.0, -1.8, 0.0};
  Harness a(GetParam(), start_in_wall, 1);
  EXPECT_EQ(a.planner().step(), PlannerStatus::invalid_start);
  const std::uint64_t checks = a.planner().stats().collision_checks;
  EXPECT_EQ(a.planner().step(), PlannerStatus::invalid_start);
  EXPECT_EQ(a.planner().stats().collision_checks, checks);
  EXPECT_EQ(a.planner().stats().iterations, 0u);

  Problem goal_in_wall = test::detour_problem();
  goal_in_wall.goal.t = {0.0, 1.8, 0.0};
  Harness b(GetParam(), goal_in_wall, 1);
  EXPECT_EQ(b.planner().solve({}), PlannerStatus::invalid_goal);

  Harness c(GetParam(), test::detour_problem(), 1);
  Termination t;
  t.max_iterations = 200000;
  ASSERT_EQ(c.planner().solve(t), PlannerStatus::solved);
  const std::size_t nodes = c.planner().stats().nodes;
  EXPECT_EQ(c.planner().step(), PlannerStatus::solved);
  EXPECT_EQ(c.planner().stats().nodes, nodes);
}

TEST_P(Conformance, TheRegistryRefusesAMisusedOperator) {
  const PlannerEntry& e = *find_planner(GetParam());
  test::ProblemFixture f(test::detour_problem());
  const std::string message = test::error_message<std::invalid_argument>([&] {
    VirtualTimeFeed* none = nullptr;
    Interaction interaction{none};
    (void)make_planner(e.name, f.validator, f.problem.start, f.problem.goal, {},
                       e.uses_operator ? nullptr : &interaction);
  });
  EXPECT_THAT(message, HasSubstr("planner '" + std::string(e.name) + "'"));
  EXPECT_THAT(message, HasSubstr(e.uses_operator ? "needs an operator" : "cannot use an operator"));
}

INSTANTIATE_TEST_SUITE_P(EveryRegisteredPlanner, Conformance, ::testing::ValuesIn(planner_names()),
                         [](const auto& p) {
                           std::string n = p.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c)))
                               c = '_';
                           return n;
                         });

TEST(Registry, UnknownPlannerNamesTheKnownOnes) {
  test::ProblemFixture f(test::detour_problem());
  EXPECT_THAT(test::error_message<std::invalid_argument>([&] {
                (void)make_planner("teleport", f.validator, f.problem.start, f.problem.goal, {});
              }),
              HasSubstr("unknown planner 'teleport' (known: birrt, rrt, birrt+rrt, interactive"));
}

}  // namespace
}  // namespace tandem
