// Contact_Shooter (Blin et al. 2016, Algorithm 2).

#include "tandem/sampling/contact_sampler.hpp"

#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/interaction/contact_frame.hpp"
#include "tandem/interaction/interaction_settings.hpp"

namespace tandem {
namespace {

using test::at;
using test::FloorScene;

TEST(ContactSampler, SamplesTouchTheObstacleWithTheOperatorsOrientation) {
  FloorScene f;
  const SE3Space& space = f.problem.space;
  CollisionChecker checker(f.problem.scene);
  const Config q_device = at(-1, 0.5, 0.3, 0.4);  // 10 cm above the floor, turned
  const auto frame = find_local_frame(checker.nearest_obstacle(q_device), q_device);
  ASSERT_TRUE(frame);
  const double clearance = 1e-3;
  Rng rng(5);
  int on_floor = 0;
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  for (int i = 0; i < 2000; ++i) {
    const auto q = sample_contact(*frame, q_device.q, space, clearance, rng);
    ASSERT_TRUE(q);
    ASSERT_TRUE(space.satisfies_bounds(*q));
    ASSERT_TRUE(q->q.coeffs() == q_device.q.coeffs());
    // On the plane: the bottom face 1 mm above the floor.
    ASSERT_NEAR(q->t.z(), 0.2 + clearance, 1e-12);
    lo = lo.cwiseMin(q->t.head<2>());
    hi = hi.cwiseMax(q->t.head<2>());
    const NearestObstacle n = checker.nearest_obstacle(*q);
    if (checker.obstacle_name(n.obstacle) == "floor") {
      ++on_floor;
      ASSERT_FALSE(n.in_collision);
      ASSERT_NEAR(n.distance, clearance, 1e-9);  // it really touches, within the clearance
    }
  }
  EXPECT_GT(on_floor, 1500);
  // The samples cover the plane inside the bounds.
  EXPECT_LT(lo.x(), -2.8);
  EXPECT_GT(hi.x(), 1.6);
  EXPECT_LT(lo.y(), -2.8);
  EXPECT_GT(hi.y(), 2.8);
}

TEST(ContactSampler, SlidesAlongAWall) {
  FloorScene f;
  CollisionChecker checker(f.problem.scene);
  const Config q_device = at(1.2, 0, 1.0);  // the bar's end 0.2 from the wall
  const auto frame = find_local_frame(checker.nearest_obstacle(q_device), q_device);
  ASSERT_TRUE(frame);
  EXPECT_EQ(checker.obstacle_name(frame->obstacle), "wall");
  EXPECT_TRUE(frame->n.isApprox(-Eigen::Vector3d::UnitX(), 1e-9));
  Rng rng(6);
  for (int i = 0; i < 200; ++i) {
    const auto q = sample_contact(*frame, q_device.q, f.problem.space, 1e-3, rng);
    ASSERT_TRUE(q);
    ASSERT_NEAR(q->t.x(), 2.0 - 0.5 - 1e-3, 1e-12);
  }
}

TEST(ContactSampler, SamplesALineInPlanarSpaces) {
  Problem p = FloorScene::make();
  const SE3Space plane(SpaceKind::planar, Bounds{{-3, -3, 1}, {1.8, 3, 1}});
  CollisionChecker checker(p.scene);
  const Config q_device = plane.planar_config(1.2, 0, 0);
  const auto frame = find_local_frame(checker.nearest_obstacle(q_device), q_device);
  ASSERT_TRUE(frame);
  Rng rng(7);
  for (int i = 0; i < 200; ++i) {
    const auto q = sample_contact(*frame, q_device.q, plane, 1e-3, rng);
    ASSERT_TRUE(q);
    ASSERT_NEAR(q->t.x(), 1.5 - 1e-3, 1e-12);
    ASSERT_DOUBLE_EQ(q->t.z(), 1.0);
    ASSERT_TRUE(plane.satisfies_bounds(*q));
  }
}

// An exact last-valid sweep stops in front of an obstacle at kSweepStopSteps translation steps, so
// a contact node nearer than that could not be extended along its surface: under exact validation
// the default clearance lies above the stop, and slides between contact samples are valid.
TEST(ContactSampler, ExactSweepsSlideBetweenSamplesAtTheDefaultClearance) {
  FloorScene f;
  const SE3Space& space = f.problem.space;
  CollisionChecker checker(f.problem.scene);
  MotionValidator validator(space, checker, {.mode = MotionValidation::exact});
  const InteractionSettings defaults;
  const double step = space.translation_step();
  EXPECT_DOUBLE_EQ(contact_clearance(defaults, space, MotionValidation::discrete), 0.1 * step);
  const double clearance = contact_clearance(defaults, space, MotionValidation::exact);
  EXPECT_GT(clearance, kSweepStopSteps * step);
  const Config q_device = at(-1, 0.5, 0.3, 0.4);
  const auto frame = find_local_frame(checker.nearest_obstacle(q_device), q_device);
  ASSERT_TRUE(frame);
  Rng rng(8);
  const auto sample = [&](double c) {
    std::optional<Config> q;
    while (!q || checker.obstacle_name(checker.nearest_obstacle(*q).obstacle) != "floor")
      q = sample_contact(*frame, q_device.q, space, c, rng);
    return *q;
  };
  for (int i = 0; i < 20; ++i) {
    const Config a = sample(clearance), b = sample(clearance);
    ASSERT_TRUE(validator.is_valid(a));
    EXPECT_TRUE(validator.check_motion_last_valid(a, b).valid);
  }
  // Nearer than the stop, the sweep does not leave its start.
  const double near = 0.5 * kSweepStopSteps * step;
  const Config a = sample(near), b = sample(near);
  ASSERT_TRUE(validator.is_valid(a));
  const MotionCheck stuck = validator.check_motion_last_valid(a, b);
  EXPECT_FALSE(stuck.valid);
  EXPECT_EQ(stuck.last_valid_step, 0U);
}

}  // namespace
}  // namespace tandem
