// Automatic authority sharing: alpha follows each side's share of the progress per extension.

#include "tandem/sampling/auto_alpha.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

TEST(AutoAlpha, StartsEvenFollowsTheSideThatMakesProgressAndKeepsAFloor) {
  AutoAlpha a(1e-6);
  EXPECT_EQ(a.alpha(), 0.5);
  // The computer's iterations carry the trees on, the operator's do not.
  for (int k = 0; k < 5000; ++k) {
    a.record(true, 0.01, 1);
    a.record(false, 0.0, 1);
  }
  EXPECT_EQ(a.alpha(), 1.0 - AutoAlpha::kFloor);
  EXPECT_NEAR(a.computer_rate(), 0.01, 1e-12);
  // Then the random trees stall before a passage and the operator's way goes on: within a few
  // memories, alpha turns to the operator.
  for (int k = 0; k < 5000; ++k) {
    a.record(true, 0.0, 1);
    a.record(false, 0.002, 1);
  }
  EXPECT_EQ(a.alpha(), AutoAlpha::kFloor);
  // Both making progress: shares in proportion to the progress per extension. An operator's
  // iteration in contact mode has ten extensions: its progress is weighed by them.
  for (int k = 0; k < 20000; ++k) {
    a.record(true, 0.003, 1);
    a.record(false, 0.01, 10);
  }
  EXPECT_NEAR(a.alpha(), 0.75, 0.01);
}

TEST(AutoAlpha, WithoutProgressOnEitherSideDriftsBackToEvenShares) {
  AutoAlpha a(1e-6);
  for (int k = 0; k < 2000; ++k)
    a.record(true, 0.01, 1);
  ASSERT_GT(a.alpha(), 0.8);
  for (int k = 0; k < 30000; ++k) {
    a.record(true, 0.0, 1);
    a.record(false, 0.0, 1);
  }
  EXPECT_NEAR(a.alpha(), 0.5, 0.05);
}

/// The interactive planner with automatic alpha on the wall-with-gap problem: its alpha moves
/// away from even shares, stays within the floor, and is reported; pinned, it is the setting.
TEST(AutoAlpha, ThePlannerCreditsProgressAndReportsTheAlphaInForce) {
  test::OperatorFixture f;
  PlannerSettings settings;
  settings.seed = 5;
  settings.interaction.auto_alpha = true;
  settings.interaction.alpha = 0.5;
  VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
  const Interaction interaction{&feed};
  auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                              &interaction);
  bool moved = false;
  for (int k = 0; k < 400 && planner->step() == PlannerStatus::running; ++k) {
    const double alpha = planner->stats().alpha;
    ASSERT_GE(alpha, AutoAlpha::kFloor);
    ASSERT_LE(alpha, 1.0 - AutoAlpha::kFloor);
    moved = moved || alpha != 0.5;
  }
  EXPECT_TRUE(moved);

  settings.interaction.auto_alpha = false;
  settings.interaction.alpha = 0.3;
  auto pinned = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                             &interaction);
  (void)pinned->step();
  (void)pinned->step();
  EXPECT_EQ(pinned->stats().alpha, 0.3);
  auto alone = make_planner("birrt", f.validator, f.problem.start, f.problem.goal, settings);
  (void)alone->step();
  EXPECT_TRUE(std::isnan(alone->stats().alpha));
}

}  // namespace
}  // namespace tandem
