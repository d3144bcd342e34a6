// The I-RRT (Taix and Flavigne 2011).

#include "tandem/planning/irrt.hpp"

#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using Fixture = test::OperatorFixture;

class IrrtModes : public ::testing::TestWithParam<IrrtSampling> {};

TEST_P(IrrtModes, FollowTheUserToTheGoal) {
  Fixture f;
  PlannerSettings settings;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.sampling = GetParam();
  VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
  LatestValue<Guidance> guidance;
  const Interaction interaction{&feed, nullptr, &guidance};
  auto planner =
      make_planner("irrt", f.validator, f.problem.start, f.problem.goal, settings, &interaction);
  Termination t;
  t.max_iterations = 400000;
  ASSERT_EQ(planner->solve(t), PlannerStatus::solved);
  EXPECT_TRUE(check_path(planner->solution(), f.validator).valid);
  const PlannerStats& s = planner->stats();
  EXPECT_GT(s.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)], s.nodes / 2);
  EXPECT_EQ(s.extensions_collision + s.extensions_reached + s.extensions_obstacle, s.iterations);
  ASSERT_NE(guidance.latest(), nullptr);
  EXPECT_GT(guidance.latest()->iteration, 0u);
}

INSTANTIATE_TEST_SUITE_P(AllModes, IrrtModes,
                         ::testing::Values(IrrtSampling::mag, IrrtSampling::path,
                                           IrrtSampling::mag_cs, IrrtSampling::path_cs),
                         [](const auto& test_info) {
                           std::string n(to_string(test_info.param));
                           for (char& c : n)
                             c = c == '+' ? '_' : c;
                           return n;
                         });

TEST(IRRT, UniformSamplesOnlyInCsModes) {
  for (IrrtSampling mode : {IrrtSampling::mag, IrrtSampling::mag_cs}) {
    Fixture f;
    PlannerSettings settings;
    settings.goal_bias = 0.0;
    settings.extend = ExtendMode::last_valid;
    settings.interaction.sampling = mode;
    VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
    const Interaction interaction{&feed};
    auto planner =
        make_planner("irrt", f.validator, f.problem.start, f.problem.goal, settings, &interaction);
    Termination t;
    t.max_iterations = 3000;
    planner->solve(t);
    const auto random =
        planner->stats().nodes_by_source[static_cast<std::size_t>(NodeSource::random)];
    if (mode == IrrtSampling::mag) {
      EXPECT_EQ(random, 0u);
    } else {
      EXPECT_GT(random, 0u);
    }
  }
}

TEST(IRRT, TheGuidanceForcePullsTheUserTowardTheTree) {
  // The user runs ahead of the tree (it cannot follow through the wall): F_a points back toward the
  // nodes, and nodes that keep failing carry a collision label.
  Fixture f;
  std::vector<Config> keys(2);
  keys[0] = f.problem.start;
  keys[1].t = {2, 2, 0};  // straight through the wall
  const auto source = std::make_shared<GuideFollower>(
      f.problem.space, keys, operator_profile("experienced", f.problem.space, OperatorClock::ticks),
      1);
  PlannerSettings settings;
  settings.goal_bias = 0.0;
  settings.extend = ExtendMode::last_valid;
  // The thresholds below were measured with the discrete check (the exact one grows another tree:
  // fa.x() = -0.47 at the end instead of below -0.5).
  settings.validation = MotionValidation::discrete;
  VirtualTimeFeed feed(OperatorModel(f.checker, source));
  LatestValue<Guidance> guidance;
  const Interaction interaction{&feed, nullptr, &guidance};
  IRRT planner(f.validator, f.problem.start, f.problem.goal, settings, interaction);
  Termination t;
  t.max_iterations = 20000;
  planner.solve(t);
  const Twist fa = guidance.latest()->force;
  EXPECT_LT(fa.x(), -0.5);  // the user is past the wall at x = 2, the tree stays at x < 0
  double worst = 0.0;
  for (const auto& l : planner.labels())
    worst = std::max(worst, l.collision_label);
  EXPECT_GT(worst, 0.1);
  for (std::size_t i = 0; i < planner.labels().size(); ++i) {
    ASSERT_DOUBLE_EQ(planner.labels()[i].distance_to_goal,
                     f.problem.space.distance(planner.trees()[0]->nodes[i], f.problem.goal));
  }
}

TEST(IRRT, IsDeterministicForASeedAndAnOperator) {
  auto run = [](std::uint64_t seed) {
    Fixture f;
    PlannerSettings settings;
    settings.seed = seed;
    settings.interaction.sampling = IrrtSampling::path_cs;
    VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
    const Interaction interaction{&feed};
    auto planner =
        make_planner("irrt", f.validator, f.problem.start, f.problem.goal, settings, &interaction);
    Termination t;
    t.max_iterations = 2000;
    planner->solve(t);
    return planner->trees()[0]->nodes;
  };
  EXPECT_EQ(run(3), run(3));
  EXPECT_NE(run(3), run(4));
}

}  // namespace
}  // namespace tandem
