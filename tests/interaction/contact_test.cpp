// Find_Local_Frame and Contact_Shooter (Blin et al. 2016, Algorithm 2).

#include <gtest/gtest.h>

#include <numbers>

#include "support/test_support.hpp"
#include "tandem/interaction/contact_frame.hpp"
#include "tandem/sampling/contact_sampler.hpp"

namespace tandem {
namespace {

TEST(GramSchmidt, GivesARightHandedOrthonormalFrameAroundN) {
  Rng rng(1);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d n =
        Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)).normalized();
    const Eigen::Matrix3d R = gram_schmidt(n);
    ASSERT_TRUE((R.transpose() * R).isIdentity(1e-12));
    ASSERT_NEAR(R.determinant(), 1.0, 1e-12);
    ASSERT_TRUE(R.col(2).isApprox(n, 1e-12));
  }
}

/// A 1 x 0.4 x 0.4 bar above a floor (top face at z = 0) and beside a wall (face at x = 2).
struct FloorScene {
  Problem problem;
  FloorScene() : problem(make()) {}
  static Problem make() {
    Scene s;
    s.object.name = "bar";
    s.object.parts.push_back({Box{{1.0, 0.4, 0.4}}, Eigen::Isometry3d::Identity()});
    s.obstacles.push_back(test::box_body("floor", {10, 10, 0.2}, {0, 0, -0.1}));
    s.obstacles.push_back(test::box_body("wall", {0.2, 10, 4}, {2.1, 0, 2}));
    Config start, goal;
    start.t = {-2, 0, 1};
    goal.t = {1, 0, 1};
    return Problem{
        "floor", "test", std::move(s), SE3Space(SpaceKind::se3, Bounds{{-3, -3, 0}, {1.8, 3, 2}}),
        start,   goal,   {},           {}};
  }
};

Config at(double x, double y, double z, double yaw = 0.0) {
  Config q;
  q.t = {x, y, z};
  q.q = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return q;
}

TEST(ContactFrame, PointsFromTheObstacleToTheObject) {
  FloorScene f;
  CollisionChecker checker(f.problem.scene);
  const Config q = at(-1, 0.5, 0.25);  // bottom face 5 cm above the floor
  const auto frame = find_local_frame(checker.nearest_obstacle(q), q);
  ASSERT_TRUE(frame);
  EXPECT_EQ(checker.obstacle_name(frame->obstacle), "floor");
  EXPECT_TRUE(frame->n.isApprox(Eigen::Vector3d::UnitZ(), 1e-9));
  EXPECT_NEAR(frame->distance, 0.05, 1e-9);
  EXPECT_NEAR(frame->delta, -0.2, 1e-9);  // the nearest point is 0.2 below the centre
  EXPECT_TRUE(frame->P_c.isApprox(q.t));
  EXPECT_FALSE(
      find_local_frame(checker.nearest_obstacle(at(-1, 0, 0.1)), at(-1, 0, 0.1)));  // in the floor
}

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

}  // namespace
}  // namespace tandem
