#include "tandem/collision/motion_validator.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "support/problems.hpp"

namespace tandem {
namespace {

using Fixture = test::ProblemFixture;
using test::at;

TEST(MotionValidator, AcceptsMotionsThroughTheGapAndRejectsThoseThroughTheWall) {
  Fixture f;
  EXPECT_TRUE(f.validator.check_motion(at(-2, 0), at(2, 0)));
  EXPECT_FALSE(f.validator.check_motion(at(-2, 1), at(2, 1)));
  // Rotated a quarter turn about z, the 1 m bar does not fit the 0.6 m gap.
  Config turned = at(2, 0);
  turned.q = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
  Config turned_start = turned;
  turned_start.t.x() = -2;
  EXPECT_FALSE(f.validator.check_motion(turned_start, turned));
}

TEST(MotionValidator, ChecksTheEndStateAndEveryStep) {
  Fixture f;
  f.validator.configure({MotionValidation::discrete});
  const Config a = at(-2, 1), b = at(2, 1);
  const unsigned n = f.problem.space.segment_count(a, b);
  const std::uint64_t before = f.validator.checks();
  EXPECT_TRUE(f.validator.check_motion(at(-2, 1), at(-1, 1)));
  EXPECT_EQ(f.validator.checks() - before, f.problem.space.segment_count(at(-2, 1), at(-1, 1)));
  EXPECT_GT(n, 10u);
  // Out of bounds counts as invalid.
  EXPECT_FALSE(f.validator.check_motion(at(2, 0), at(4, 0)));
}

TEST(MotionValidator, ReportsTheLastValidConfiguration) {
  Fixture f;
  f.validator.configure({MotionValidation::discrete});
  const Config a = at(-2, 1), b = at(2, 1);
  const MotionCheck r = f.validator.check_motion_last_valid(a, b);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.steps, f.problem.space.segment_count(a, b));
  EXPECT_TRUE(r.last_valid == f.problem.space.step(a, b, r.last_valid_step, r.steps));
  // The bar (half length 0.5) stops short of the wall's face at x = -0.05, within one step.
  EXPECT_LT(r.last_valid.t.x() + 0.5, -0.05);
  EXPECT_GT(r.last_valid.t.x() + 0.5, -0.05 - f.problem.space.translation_step());
  EXPECT_TRUE(f.validator.is_valid(r.last_valid));

  const MotionCheck through = f.validator.check_motion_last_valid(at(-2, 0), at(2, 0));
  EXPECT_TRUE(through.valid);
  EXPECT_TRUE(through.last_valid == at(2, 0));
}

}  // namespace
}  // namespace tandem
