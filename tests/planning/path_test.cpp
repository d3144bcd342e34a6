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

/// The box [-1, 1]^3 and a cube of half-side 0.1 about the object frame's origin.
GoalRegion unit_box_region() {
  GoalRegion r;
  r.min = Eigen::Vector3d::Constant(-1.0);
  r.max = Eigen::Vector3d::Constant(1.0);
  for (double x : {-0.1, 0.1})
    for (double y : {-0.1, 0.1})
      for (double z : {-0.1, 0.1})
        r.points.emplace_back(x, y, z);
  return r;
}

TEST(GoalRegion, ThePartIsInWhenAllOfItIsOutsideTheBox) {
  const GoalRegion r = unit_box_region();
  EXPECT_FALSE(r.contains(at(0, 0, 0)));
  EXPECT_FALSE(r.contains(at(1.05, 0, 0)));  // its near side is still inside
  EXPECT_TRUE(r.contains(at(1.15, 0, 0)));
  EXPECT_TRUE(r.contains(at(0, -1.5, 0.3)));
  // Turned 45 degrees about z, the cube reaches 0.1 sqrt(2) from its centre along x.
  EXPECT_FALSE(r.contains(at(1.13, 0, 0, M_PI / 4)));
  EXPECT_TRUE(r.contains(at(1.15, 0, 0, M_PI / 4)));
}

TEST(GoalRegion, APathIsCutWhereItFirstEntersTheRegion) {
  const GoalRegion r = unit_box_region();
  const SE3Space space(SpaceKind::se3, Bounds{{-5, -5, -5}, {5, 5, 5}});
  const Path path{at(0, 0, 0), at(0.5, 0, 0), at(3, 0, 0), at(3, 3, 0)};
  const Path cut = cut_at_goal_region(path, r, space);
  ASSERT_EQ(cut.size(), 3u);
  EXPECT_TRUE(r.contains(cut.back()));
  EXPECT_NEAR(cut.back().t.x(), 1.1, 1e-9);  // the cube's near side just past the box
  EXPECT_EQ(cut[1].t, path[1].t);
  // A path that never enters it, or starts in it, is kept whole.
  const Path inside{at(0, 0, 0), at(0.5, 0.5, 0)};
  EXPECT_EQ(cut_at_goal_region(inside, r, space).size(), 2u);
  const Path out{at(2, 0, 0), at(3, 0, 0)};
  EXPECT_EQ(cut_at_goal_region(out, r, space).size(), 2u);
}

}  // namespace
}  // namespace tandem
