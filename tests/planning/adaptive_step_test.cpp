#include "tandem/planning/adaptive_step.hpp"

#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "support/test_support.hpp"
#include "tandem/planning/extend.hpp"

namespace tandem {
namespace {

TEST(AdaptiveStep, HalvesOnABlockedExtensionAndDoublesForANewNode) {
  AdaptiveStep steps(8.0, 0.125);
  EXPECT_TRUE(steps.adapts());
  EXPECT_EQ(steps.step(0), 8.0);
  steps.blocked(0);
  EXPECT_EQ(steps.step(0), 4.0);
  for (int i = 0; i < 10; ++i)
    steps.blocked(0);
  EXPECT_EQ(steps.step(0), 1.0);  // the floor, 0.125 x 8
  steps.added(1, 0);
  EXPECT_EQ(steps.step(1), 2.0);
  steps.added(2, 1);
  steps.added(3, 2);
  steps.added(4, 3);
  EXPECT_EQ(steps.step(4), 8.0);  // at most the range
  EXPECT_EQ(steps.step(7), 8.0);  // not seen yet: the range
}

TEST(AdaptiveStep, AFloorOfOneKeepsTheRange) {
  AdaptiveStep steps(8.0, 1.0);
  EXPECT_FALSE(steps.adapts());
  steps.blocked(0);
  EXPECT_EQ(steps.step(0), 8.0);
}

// The floor falls with the search's queries: halved at 100 000, again at 400 000, 1 600 000, ...,
// down to 1/128 of the range; a node's step then shrinks below the old floor.
TEST(AdaptiveStep, TheFloorFallsAsTheSearchGoesOnWithoutAPath) {
  AdaptiveStep steps(8.0, 0.125);
  const auto floor_step = [&steps] {
    for (int i = 0; i < 20; ++i)
      steps.blocked(0);
    return steps.step(0);
  };
  steps.relax(99999);
  EXPECT_EQ(steps.floor(), 0.125);
  EXPECT_EQ(floor_step(), 1.0);
  steps.relax(100000);
  EXPECT_EQ(steps.floor(), 0.0625);
  EXPECT_EQ(floor_step(), 0.5);
  steps.relax(399999);
  EXPECT_EQ(steps.floor(), 0.0625);
  steps.relax(400000);
  EXPECT_EQ(steps.floor(), 1.0 / 32.0);
  steps.relax(100000000);  // 1 600 000 and 6 400 000 passed, and more
  EXPECT_EQ(steps.floor(), 1.0 / 128.0);
  EXPECT_EQ(floor_step(), 8.0 / 128.0);
  steps.added(1, 0);
  EXPECT_EQ(steps.step(1), 2.0 * 8.0 / 128.0) << "a new node still starts at twice its parent's";
}

TEST(AdaptiveStep, RelaxingNeitherRaisesALowerFloorNorMovesAFixedStep) {
  AdaptiveStep low(8.0, 1.0 / 512.0);
  low.relax(100000000);
  EXPECT_EQ(low.floor(), 1.0 / 512.0);
  AdaptiveStep fixed(8.0, 1.0);
  fixed.relax(100000000);
  EXPECT_FALSE(fixed.adapts());
  fixed.blocked(0);
  EXPECT_EQ(fixed.step(0), 8.0);
}

TEST(AdaptiveStep, OnlyTheClassicExtensionAdapts) {
  PlannerSettings s;
  s.extend = ExtendMode::classic;
  EXPECT_EQ(adaptive_floor(s), s.adaptive_step);
  s.extend = ExtendMode::last_valid;
  EXPECT_EQ(adaptive_floor(s), 1.0);
}

// EXTEND takes q_near's step and reports back: blocked by the wall, the root's step halves, and the
// next extension from it goes half as far.
TEST(AdaptiveStep, ExtendGoesByTheNearNodesStep) {
  test::ProblemFixture f;
  Tree tree(f.problem.space, "kdtree", test::at(-2, 1));
  AdaptiveStep steps(2.0, 0.125);
  const Extension through_wall = extend(tree, test::at(2, 1), 2.0, f.validator, ExtendMode::classic,
                                        NodeSource::random, &steps);
  EXPECT_EQ(through_wall.status, ExtendStatus::trapped);
  EXPECT_EQ(steps.step(0), 1.0);
  const Extension away = extend(tree, test::at(-2, -2.5), 2.0, f.validator, ExtendMode::classic,
                                NodeSource::random, &steps);
  ASSERT_EQ(away.status, ExtendStatus::advanced);
  EXPECT_NEAR(f.problem.space.distance(tree.nodes[0], tree.nodes[away.node]), 1.0, 1e-9);
  EXPECT_EQ(steps.step(away.node), 2.0);
}

}  // namespace
}  // namespace tandem
