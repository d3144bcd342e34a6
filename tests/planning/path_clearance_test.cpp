#include "tandem/planning/path_clearance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/test_support.hpp"

namespace tandem {
namespace {

using test::at;

/// A box as a triangle mesh (FCL's mesh distances are exact, its primitives' GJK ones are not).
Body mesh_box(const std::string& name, const Eigen::Vector3d& size, const Eigen::Vector3d& at) {
  Body b;
  b.name = name;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = at;
  b.parts.push_back(
      {MeshShape{std::make_shared<const TriangleMesh>(tessellate(Box{size})), name}, X});
  return b;
}

/// A cube of side 0.2 about the object frame's origin, and a pillar whose lower face is at y = 0.5
/// and which spans x in [-0.05, 0.05].
struct PillarScene {
  Scene scene;
  SE3Space space{SpaceKind::se3, Bounds{{-3, -3, -3}, {3, 3, 3}}};
  PillarScene() {
    scene.object = mesh_box("cube", Eigen::Vector3d::Constant(0.2), Eigen::Vector3d::Zero());
    scene.obstacles.push_back(
        mesh_box("floor", Eigen::Vector3d(4, 4, 0.1), Eigen::Vector3d(0, 0, -2)));
    scene.obstacles.push_back(mesh_box("pillar", Eigen::Vector3d(0.1, 1, 2), {0, 1, 0}));
  }
};

TEST(PathClearance, StatesGetFclsDistanceAndMotionsTheirTrueMinimumFromBelow) {
  PillarScene s;
  CollisionChecker checker(s.scene);
  // Passing under the pillar: 0.4 from it while the cube is under it, farther at both ends.
  const Path path{at(-1, 0, 0), at(1.3, 0, 0)};
  const PathClearance c = path_clearance(path, checker, s.space, 0.01, 1e-12);
  ASSERT_EQ(c.states.size(), 2u);
  EXPECT_NEAR(c.states[0].distance, std::hypot(0.85, 0.4), 1e-12);
  EXPECT_NEAR(c.states[1].distance, std::hypot(1.15, 0.4), 1e-12);
  EXPECT_EQ(checker.obstacle_name(c.states[0].obstacle), "pillar");
  ASSERT_EQ(c.segments.size(), 1u);
  const SegmentClearance& m = c.segments[0];
  EXPECT_LE(m.lower, 0.4 + 1e-12);  // never above the true minimum
  EXPECT_GE(m.lower, 0.99 * m.found);
  EXPECT_GE(m.found, 0.4 - 1e-12);
  EXPECT_EQ(checker.obstacle_name(m.obstacle), "pillar");
  EXPECT_DOUBLE_EQ(c.lower(), m.lower);
}

TEST(PathClearance, ATurnsMinimumBetweenItsStatesIsFound) {
  PillarScene s;
  CollisionChecker checker(s.scene);
  // Turning 80 degrees about z under the pillar: a corner comes closest at 45 degrees, a
  // fraction 0.5625 of the motion that no state and no early bisection point falls on.
  const Path path{at(0, 0, 0, 0.0), at(0, 0, 0, 80.0 * M_PI / 180.0)};
  const double truth = 0.5 - 0.1 * std::sqrt(2.0);
  for (double accuracy : {0.01, 1e-4}) {
    const PathClearance c = path_clearance(path, checker, s.space, accuracy, 1e-12);
    const SegmentClearance& m = c.segments[0];
    EXPECT_LE(m.lower, truth + 1e-12) << accuracy;
    EXPECT_GE(m.lower, truth * (1.0 - accuracy) - 1e-12) << accuracy;
    EXPECT_NEAR(m.at, 0.5625, 0.05) << accuracy;
    EXPECT_GT(c.states[0].distance, truth + 0.04);  // the ends are farther (0.4 at 0 degrees)
  }
}

TEST(PathClearance, ACollidingMotionHasNoClearance) {
  PillarScene s;
  CollisionChecker checker(s.scene);
  const Path path{at(0, 0, 0), at(0, 2, 0)};  // up through the pillar
  const PathClearance c = path_clearance(path, checker, s.space, 0.01, 1e-12);
  EXPECT_EQ(c.lower(), 0.0);
  EXPECT_THROW(path_clearance(path, checker, s.space, 0.0, 1e-12), std::invalid_argument);
}

}  // namespace
}  // namespace tandem
