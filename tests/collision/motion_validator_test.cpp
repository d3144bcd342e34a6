#include "tandem/collision/motion_validator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/problems.hpp"
#include "tandem/core/error.hpp"

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

TEST(MotionValidator, AClearanceKeepsEveryConfigurationOfAMotionThatFarFromTheObstacles) {
  Fixture f;
  // Through the middle of the 0.6 m gap, the 0.2 m wide bar is 0.2 m from either side.
  const Config a = at(-2, 0), b = at(2, 0);
  for (double clearance : {0.1, 0.19}) {
    f.validator.configure({MotionValidation::exact, 0.0, true, clearance});
    EXPECT_TRUE(f.validator.check_motion(a, b)) << clearance;
    EXPECT_TRUE(f.validator.check_motion_last_valid(a, b).valid) << clearance;
  }
  for (double clearance : {0.21, 0.5}) {
    f.validator.configure({MotionValidation::exact, 0.0, true, clearance});
    EXPECT_FALSE(f.validator.check_motion(a, b)) << clearance;
    EXPECT_TRUE(f.validator.is_valid(a)) << clearance;  // 1.45 m from the wall
    // Swept toward the gap, the bar stops before its front corners are `clearance` from the
    // gap's edges, 0.2 aside: its front (0.5 ahead of its centre) 0.05 + sqrt(c^2 - 0.2^2)
    // before the wall's centre plane.
    const MotionCheck m = f.validator.check_motion_last_valid(a, b);
    EXPECT_FALSE(m.valid);
    const double front = -0.05 - std::sqrt(clearance * clearance - 0.04);
    EXPECT_LE(m.last_valid.t.x() + 0.5, front + 1e-9) << clearance;
    EXPECT_GE(m.last_valid.t.x() + 0.5, front - 0.1) << clearance;  // and not far before
  }
  EXPECT_THROW(f.validator.configure({MotionValidation::discrete, 0.0, true, 0.1}), InputError);
  EXPECT_THROW(f.validator.configure({MotionValidation::exact, 0.0, true, -0.1}), InputError);
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
