#include "tandem/planning/path.hpp"

#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using Fixture = test::ProblemFixture;
using test::at;

TEST(Path, LengthSumsTheMetric) {
  Fixture f;
  EXPECT_DOUBLE_EQ(path_length(f.problem.space, {at(0, 0), at(3, 4), at(3, 5)}), 6.0);
  EXPECT_DOUBLE_EQ(path_length(f.problem.space, {at(0, 0)}), 0.0);
}

TEST(Path, CheckFindsTheFirstInvalidStateOrMotion) {
  Fixture f;
  EXPECT_TRUE(check_path({at(-2, 0), at(2, 0)}, f.validator).valid);
  const PathCheck in_wall = check_path({at(-2, 0), at(-2, 1), at(0, 1), at(2, 1)}, f.validator);
  EXPECT_FALSE(in_wall.valid);
  EXPECT_EQ(in_wall.index, 2u);
  EXPECT_FALSE(in_wall.motion);
  EXPECT_EQ(in_wall.describe(), "state 2 is in collision");
  const PathCheck through = check_path({at(-2, 0), at(-2, 1), at(2, 1)}, f.validator);
  EXPECT_FALSE(through.valid);
  EXPECT_EQ(through.index, 2u);
  EXPECT_TRUE(through.motion);
  EXPECT_EQ(through.describe(), "the motion from state 1 to state 2 collides");
  const PathCheck outside = check_path({at(-2, 0), at(-9, 0)}, f.validator);
  EXPECT_TRUE(outside.out_of_bounds);
  EXPECT_EQ(outside.describe(), "state 1 is outside the bounds");
}

TEST(Path, SimplifyKeepsValidityAndEndsAndNeverLengthens) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Fixture f;
    PlannerSettings settings;
    settings.seed = seed;
    settings.range = 0.7;
    auto planner = make_planner("birrt", f.validator, f.problem.start, f.problem.goal, settings);
    ASSERT_EQ(planner->solve(Termination{}), PlannerStatus::solved);
    const Path raw = planner->solution();
    Rng rng(seed);
    const Path simple = simplify_path(raw, f.validator, rng);
    EXPECT_TRUE(check_path(simple, f.validator).valid) << seed;
    EXPECT_TRUE(simple.front() == raw.front());
    EXPECT_TRUE(simple.back() == raw.back());
    EXPECT_LE(path_length(f.problem.space, simple), path_length(f.problem.space, raw) + 1e-9);
  }
}

TEST(Path, SimplifyStraightensAZigzagThroughFreeSpace) {
  Fixture f;
  const Path zigzag = {at(-2.5, 0), at(-2, 1), at(-1.5, -1), at(-1, 1), at(-0.8, 0)};
  Rng rng(1);
  const Path simple = simplify_path(zigzag, f.validator, rng);
  EXPECT_EQ(simple.size(), 2u);
  EXPECT_NEAR(path_length(f.problem.space, simple), 1.7, 1e-9);
}

}  // namespace
}  // namespace tandem
