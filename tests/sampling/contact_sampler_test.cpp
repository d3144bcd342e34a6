// Contact_Shooter (Blin et al. 2016, Algorithm 2).

#include "tandem/sampling/contact_sampler.hpp"

#include <gtest/gtest.h>

#include <numbers>

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

/// The floor scene with a second wall across y (its face at y = 2): a corner of three surfaces at
/// x = 2, y = 2, z = 0 (bounds up to x 1.8, y 1.8).
Problem corner_problem() {
  Problem p = FloorScene::make();
  p.scene.obstacles.push_back(test::box_body("side", {10, 0.2, 4}, {0, 2.1, 2}));
  p.space = SE3Space(SpaceKind::se3, Bounds{{-3, -3, 0}, {1.8, 1.8, 2}});
  return p;
}

/// The operator's frame and those of the other surfaces within d, distinct (as AuthoritySharing
/// takes them).
std::vector<ContactFrame> surfaces_at(CollisionChecker& checker, const Config& q, double d,
                                      std::size_t most) {
  std::vector<ContactFrame> frames{*find_local_frame(checker.nearest_obstacle(q), q)};
  for (const NearestObstacle& n : checker.nearest_surfaces(q, d))
    frames.push_back(*find_local_frame(n, q));
  return distinct_surfaces(frames, most);
}

TEST(ContactSurfaces, AnEdgeGivesSamplesOnTheLineAboveBothPlanes) {
  FloorScene f;
  const SE3Space& space = f.problem.space;
  CollisionChecker checker(f.problem.scene);
  // The bar 0.1 above the floor and 0.1 from the wall (its faces at z = 0.1, x = 1.9).
  const Config q_device = at(1.4, 0.3, 0.3);
  const std::vector<ContactFrame> frames = surfaces_at(checker, q_device, 0.15, 3);
  ASSERT_EQ(frames.size(), 2u);
  const double clearance = 1e-3;
  Rng rng(3);
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 500; ++i) {
    const auto q = sample_contact_surfaces(frames, q_device.q, space, clearance, 0.0, rng);
    ASSERT_TRUE(q);
    ASSERT_TRUE(q->q.coeffs().isApprox(q_device.q.coeffs(), 1e-15));
    // On the edge: the bottom face 1 mm above the floor, the end face 1 mm from the wall.
    ASSERT_NEAR(q->t.z(), 0.2 + clearance, 1e-9);
    ASSERT_NEAR(q->t.x(), 1.5 - clearance, 1e-9);
    lo = std::min(lo, q->t.y());
    hi = std::max(hi, q->t.y());
    for (const NearestObstacle& n : checker.nearest_surfaces(*q, 0.01))
      ASSERT_NEAR(n.distance, clearance, 1e-9) << checker.obstacle_name(n.obstacle);
  }
  // Along the whole edge inside the bounds.
  EXPECT_LT(lo, -2.8);
  EXPECT_GT(hi, 2.8);
}

TEST(ContactSurfaces, ACornerGivesThePointAboveAllThreePlanes) {
  const Problem p = corner_problem();
  CollisionChecker checker(p.scene);
  const Config q_device = at(1.4, 1.7, 0.3);  // 0.1 from the floor, the wall and the side wall
  const std::vector<ContactFrame> frames = surfaces_at(checker, q_device, 0.15, 3);
  ASSERT_EQ(frames.size(), 3u);
  const double clearance = 1e-3;
  Rng rng(3);
  const auto q = sample_contact_surfaces(frames, q_device.q, p.space, clearance, 0.0, rng);
  ASSERT_TRUE(q);
  EXPECT_TRUE(
      q->t.isApprox(Eigen::Vector3d(1.5 - clearance, 1.8 - clearance, 0.2 + clearance), 1e-9));
  const std::vector<NearestObstacle> touching = checker.nearest_surfaces(*q, 0.01);
  ASSERT_EQ(touching.size(), 3u);
  for (const NearestObstacle& n : touching)
    EXPECT_NEAR(n.distance, clearance, 1e-9) << checker.obstacle_name(n.obstacle);
  // Asked for two surfaces, it slides along the edge of the nearest two instead.
  EXPECT_EQ(surfaces_at(checker, q_device, 0.15, 2).size(), 2u);
}

TEST(ContactSurfaces, SurfacesWhoseNormalsAreWithin30DegreesCountOnce) {
  ContactFrame floor, tilted, wall;
  floor.n = Eigen::Vector3d::UnitZ();
  tilted.n = Eigen::Vector3d(0, 0.5, 1).normalized();  // 26.6 degrees from the floor's
  wall.n = -Eigen::Vector3d::UnitX();
  const auto kept = distinct_surfaces({floor, tilted, wall}, 3);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].n, floor.n);
  EXPECT_EQ(kept[1].n, wall.n);
  EXPECT_EQ(distinct_surfaces({floor, tilted, wall}, 1).size(), 1u);
}

TEST(ContactSurfaces, TurnsInContactAreAboutTheNormalAndKeepTheFaceOnThePlane) {
  FloorScene f;
  CollisionChecker checker(f.problem.scene);
  const Config q_device = at(-1, 0.5, 0.3, 0.4);  // 10 cm above the floor, turned 0.4 about z
  const auto frame = find_local_frame(checker.nearest_obstacle(q_device), q_device);
  ASSERT_TRUE(frame);
  const double turn = 20.0 * std::numbers::pi / 180.0, clearance = 1e-3;
  Rng rng(9);
  double least = 1e9, most = -1e9;
  for (int i = 0; i < 500; ++i) {
    const auto q =
        sample_contact_surfaces({*frame}, q_device.q, f.problem.space, clearance, turn, rng);
    ASSERT_TRUE(q);
    // The change of orientation is a turn about the floor's normal, within the limit.
    const Eigen::AngleAxisd change(q->q * q_device.q.conjugate());
    const double angle = change.angle() * (change.axis().z() < 0 ? -1.0 : 1.0);
    ASSERT_LE(std::abs(angle), turn + 1e-12);
    if (std::abs(angle) > 1e-9) {
      ASSERT_NEAR(std::abs(change.axis().z()), 1.0, 1e-9);
    }
    least = std::min(least, angle);
    most = std::max(most, angle);
    ASSERT_NEAR(q->t.z(), 0.2 + clearance, 1e-9);  // still on the floor
  }
  EXPECT_LT(least, -0.9 * turn);
  EXPECT_GT(most, 0.9 * turn);
}

}  // namespace
}  // namespace tandem
