#include "tandem/collision/collision_checker.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <thread>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/rng.hpp"

namespace tandem {
namespace {

using test::at;
using test::box_body;
using ::testing::HasSubstr;

/// A unit cube object between a box "left" (x <= -1) and a sphere "right" centred at x = 3.
Scene two_obstacles() {
  Scene s;
  s.object.name = "cube";
  s.object.parts.push_back({Box{{1, 1, 1}}, Eigen::Isometry3d::Identity()});
  s.obstacles.push_back(box_body("left", {1, 4, 4}, {-1.5, 0, 0}));
  Body ball;
  ball.name = "right";
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(3, 0, 0);
  ball.parts.push_back({Sphere{0.5}, X});
  s.obstacles.push_back(ball);
  return s;
}

TEST(CollisionChecker, DetectsCollisionsAndFreeConfigurations) {
  CollisionChecker checker(two_obstacles());
  EXPECT_TRUE(checker.is_collision_free(at(0.4, 0, 0)));
  EXPECT_FALSE(checker.is_collision_free(at(-0.6, 0, 0)));  // the cube reaches x = -1.1
  EXPECT_FALSE(checker.is_collision_free(at(2.2, 0, 0)));   // reaches x = 2.7 inside the sphere
  // A rotated cube reaches farther: its corner at sqrt(2)/2 along x.
  Config turned = at(-0.35, 0, 0);
  EXPECT_TRUE(checker.is_collision_free(turned));
  turned.q = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitZ()));
  EXPECT_FALSE(checker.is_collision_free(turned));
  EXPECT_EQ(checker.counters().state_checks, 5u);
}

TEST(CollisionChecker, FindsTheNearestObstacleWithWorldFramePoints) {
  CollisionChecker checker(two_obstacles());
  const NearestObstacle near_left = checker.nearest_obstacle(at(0.2, 0.3, 0));
  EXPECT_FALSE(near_left.in_collision);
  EXPECT_EQ(checker.obstacle_name(near_left.obstacle), "left");
  EXPECT_NEAR(near_left.distance, 0.7, 1e-9);
  EXPECT_NEAR(near_left.point_on_object.x(), -0.3, 1e-9);
  EXPECT_NEAR(near_left.point_on_obstacle.x(), -1.0, 1e-9);
  EXPECT_NEAR((near_left.point_on_object - near_left.point_on_obstacle).norm(), near_left.distance,
              1e-9);

  const NearestObstacle near_right = checker.nearest_obstacle(at(1.5, 0, 0));
  EXPECT_EQ(checker.obstacle_name(near_right.obstacle), "right");
  EXPECT_NEAR(near_right.distance, 0.5, 1e-6);
  EXPECT_NEAR(near_right.point_on_object.x(), 2.0, 1e-6);
  EXPECT_NEAR(near_right.point_on_obstacle.x(), 2.5, 1e-6);

  const NearestObstacle inside = checker.nearest_obstacle(at(-0.7, 0, 0));
  EXPECT_TRUE(inside.in_collision);
  EXPECT_EQ(inside.distance, 0.0);
  EXPECT_EQ(checker.obstacle_name(inside.obstacle), "left");
}

Geometry unit_shape(const std::string& kind) {
  if (kind == "box")
    return Box{{1, 1, 1}};
  if (kind == "sphere")
    return Sphere{0.5};
  if (kind == "cylinder")
    return Cylinder{0.5, 1.0};
  return MeshShape{std::make_shared<TriangleMesh>(tessellate(Box{{1, 1, 1}})), "cube"};
}

class NearestPoints : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(NearestPoints, AreInTheWorldFrameOnTheRightBodies) {
  // FCL 0.7 gets these wrong for a primitive before a mesh and for spheres against meshes; the
  // checker must not pass that on. Object and obstacle are turned and apart; each nearest point
  // must lie on (within the bounding sphere of) its own body, and the two must be `distance` apart.
  Scene s;
  s.object.name = "object";
  s.object.parts.push_back({unit_shape(std::get<0>(GetParam())), Eigen::Isometry3d::Identity()});
  Body obstacle;
  obstacle.name = "obstacle";
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
  X_WB.translation() = Eigen::Vector3d(-2, 1.2, 2.9);
  X_WB.linear() = Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  obstacle.parts.push_back({unit_shape(std::get<1>(GetParam())), X_WB});
  s.obstacles.push_back(obstacle);
  CollisionChecker checker(s);
  Config q = at(0.3, 1, 3);
  q.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  const NearestObstacle n = checker.nearest_obstacle(q);
  ASSERT_FALSE(n.in_collision);
  EXPECT_GT(n.distance, 1.0);
  EXPECT_LT((n.point_on_object - q.t).norm(), 0.87);
  EXPECT_LT((n.point_on_obstacle - X_WB.translation()).norm(), 0.87);
  EXPECT_NEAR((n.point_on_object - n.point_on_obstacle).norm(), n.distance, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(AllPairs, NearestPoints,
                         ::testing::Combine(::testing::Values("mesh", "box", "sphere", "cylinder"),
                                            ::testing::Values("mesh", "box", "sphere", "cylinder")),
                         [](const auto& test_info) {
                           return std::get<0>(test_info.param) + "_to_" +
                                  std::get<1>(test_info.param);
                         });

TEST(CollisionChecker, FindsExactNearestPointsBetweenASphereAndAMesh) {
  Scene s;
  s.object.name = "ball";
  s.object.parts.push_back({Sphere{0.5}, Eigen::Isometry3d::Identity()});
  Body slab;
  slab.name = "slab";
  auto mesh = std::make_shared<TriangleMesh>(tessellate(Box{{1, 4, 4}}));
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(-2, 0, 0);
  slab.parts.push_back({MeshShape{mesh, "slab"}, X});
  s.obstacles.push_back(slab);
  CollisionChecker checker(s);
  const NearestObstacle n = checker.nearest_obstacle(at(0, 0, 0));
  EXPECT_NEAR(n.distance, 1.0, 1e-6);
  EXPECT_NEAR(n.point_on_object.x(), -0.5, 1e-6);
  EXPECT_NEAR(n.point_on_obstacle.x(), -1.5, 1e-6);
}

TEST(CollisionChecker, MeshesCollideLikeTheirPrimitives) {
  Scene prim = two_obstacles();
  Scene mesh = prim;
  mesh.object.parts[0].geometry =
      MeshShape{std::make_shared<TriangleMesh>(tessellate(Box{{1, 1, 1}})), "cube"};
  CollisionChecker a(prim), b(mesh);
  Rng rng(5);
  for (int i = 0; i < 500; ++i) {
    Config q = at(rng.uniform(-2, 3), rng.uniform(-1, 1), rng.uniform(-1, 1));
    q.q = Eigen::Quaterniond(Eigen::AngleAxisd(
        rng.uniform(0, 3), Eigen::Vector3d(rng.uniform(-1, 1), 1, 0).normalized()));
    // A cube as a triangle mesh is hollow: fully inside the slab it does not touch it (fcl #78), so
    // only compare where the cube's centre is outside the obstacles.
    if (q.t.x() < -1.0 || (q.t - Eigen::Vector3d(3, 0, 0)).norm() < 0.5)
      continue;
    ASSERT_EQ(a.is_collision_free(q), b.is_collision_free(q)) << q.t.transpose();
  }
}

TEST(CollisionChecker, ClonesShareGeometryButNotCounters) {
  CollisionChecker checker(two_obstacles());
  checker.is_collision_free(at(0, 0, 0));
  CollisionChecker other = checker.clone();
  EXPECT_EQ(other.counters().state_checks, 0u);
  // Two threads, each with its own checker, get the same answers.
  std::vector<bool> first, second;
  auto sweep = [](CollisionChecker& c, std::vector<bool>& out) {
    for (int i = 0; i < 2000; ++i)
      out.push_back(c.is_collision_free(at(-1.5 + i * 0.002, 0, 0)));
  };
  std::thread t([&] { sweep(other, second); });
  sweep(checker, first);
  t.join();
  EXPECT_EQ(first, second);
}

TEST(CollisionChecker, CountsTheWorkOfItsQueriesTheSameForTheSameQueries) {
  // The cube and the left box as meshes (tandem's walk of their trees), the sphere through FCL.
  Scene s = two_obstacles();
  s.object.parts[0].geometry = unit_shape("mesh");
  s.obstacles[0].parts[0].geometry =
      MeshShape{std::make_shared<TriangleMesh>(tessellate(Box{{1, 4, 4}})), "left"};
  CollisionChecker checker(s);
  EXPECT_EQ(query_work(checker.counters()), 0u);
  const auto ask = [](CollisionChecker& c) {
    Rng rng(4);
    for (int i = 0; i < 300; ++i) {
      const Config q = at(rng.uniform(-1.5, 3.5), rng.uniform(-1, 1), rng.uniform(-1, 1));
      c.is_collision_free(q);
      c.clearance_bound(q, 0.5);
    }
  };
  ask(checker);
  const CollisionCounters& c = checker.counters();
  EXPECT_GT(c.box_tests, 0u);
  EXPECT_GT(c.triangle_tests, 0u);
  EXPECT_GT(c.fcl_calls, 0u);
  const std::uint64_t work = query_work(c);
  // Each query's fixed part, and each test at least once.
  EXPECT_GE(work, 600u + c.box_tests + c.triangle_tests + c.fcl_calls);
  // Another checker asked the same (another thread, another time) counts the same work.
  CollisionChecker other = checker.clone();
  ask(other);
  EXPECT_EQ(other.counters().box_tests, c.box_tests);
  EXPECT_EQ(other.counters().triangle_tests, c.triangle_tests);
  EXPECT_EQ(query_work(other.counters()), work);
  // More queries, more work.
  ask(other);
  EXPECT_GT(query_work(other.counters()), work);
}

TEST(CollisionChecker, RejectsNonsensicalPrimitives) {
  Scene s = two_obstacles();
  s.obstacles[1].parts[0].geometry = Sphere{-1.0};
  EXPECT_THAT(test::error_message<InputError>([&] { return CollisionChecker{s}; }),
              HasSubstr("obstacle 'right': sphere radius must be a positive finite number, got "
                        "-1.000000"));
  Scene t = two_obstacles();
  t.object.parts.clear();
  EXPECT_THAT(test::error_message<InputError>([&] { return CollisionChecker{t}; }),
              HasSubstr("object 'cube': the moving object has no geometry"));
}

TEST(CollisionChecker, ReportsInfiniteDistanceWithoutObstacles) {
  Scene s = two_obstacles();
  s.obstacles.clear();
  CollisionChecker checker(s);
  EXPECT_TRUE(checker.is_collision_free(at(0, 0, 0)));
  EXPECT_TRUE(std::isinf(checker.nearest_obstacle(at(0, 0, 0)).distance));
}

TEST(CollisionChecker, FindsEverySurfaceNearTheObjectNearestFirst) {
  // A floor (top at z = 0), a wall (face at x = 2) and a thin plate far away; a 1 x 0.4 x 0.4 bar.
  Scene s;
  s.object.name = "bar";
  s.object.parts.push_back({Box{{1.0, 0.4, 0.4}}, Eigen::Isometry3d::Identity()});
  s.obstacles.push_back(box_body("floor", {10, 10, 0.2}, {0, 0, -0.1}));
  s.obstacles.push_back(box_body("wall", {0.2, 10, 4}, {2.1, 0, 2}));
  s.obstacles.push_back(box_body("far", {0.2, 0.2, 0.2}, {-3, -3, 1}));
  CollisionChecker checker(s);
  // 0.05 above the floor, 0.1 from the wall: both, the floor first; the far plate is not near.
  const std::vector<NearestObstacle> near = checker.nearest_surfaces(at(1.4, 0, 0.25), 0.2);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(checker.obstacle_name(near[0].obstacle), "floor");
  EXPECT_NEAR(near[0].distance, 0.05, 1e-9);
  EXPECT_NEAR(near[0].point_on_obstacle.z(), 0.0, 1e-9);
  EXPECT_EQ(checker.obstacle_name(near[1].obstacle), "wall");
  EXPECT_NEAR(near[1].distance, 0.1, 1e-9);
  EXPECT_NEAR(near[1].point_on_obstacle.x(), 2.0, 1e-9);
  // Within a smaller distance, only the floor; touching the floor, none (no direction is known).
  EXPECT_EQ(checker.nearest_surfaces(at(1.4, 0, 0.25), 0.07).size(), 1u);
  EXPECT_TRUE(checker.nearest_surfaces(at(1.4, 0, 0.15), 0.2).empty());
  EXPECT_TRUE(checker.nearest_surfaces(at(0, 0, 1.5), 0.2).empty());
}

}  // namespace
}  // namespace tandem
