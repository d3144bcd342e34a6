// Find_Local_Frame (Blin et al. 2016, Algorithm 2).

#include "tandem/interaction/contact_frame.hpp"

#include <gtest/gtest.h>

#include "support/problems.hpp"

namespace tandem {
namespace {

using test::at;
using test::FloorScene;

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

}  // namespace
}  // namespace tandem
