// The I-RRT's Gaussian shooting area (Taix and Flavigne 2011).

#include "tandem/sampling/gaussian_shooter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tandem {
namespace {

TEST(GaussianShot, IsCentredAndStretchedAlongTheForce) {
  const SE3Space space(SpaceKind::se3, Bounds{{-100, -100, -100}, {100, 100, 100}});
  Config centre;
  centre.t = {1, 2, 3};
  const double sigma_t = 0.5, sigma_r = 0.1;
  Twist force = Twist::Zero();
  force.x() = 2 * sigma_t;  // strength 2 in units of sigma: stretched 3 times along x
  Rng rng(1);
  const int n = 40000;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), var = Eigen::Vector3d::Zero();
  double angle = 0.0;
  for (int i = 0; i < n; ++i) {
    const Config q = gaussian_shot(space, centre, force, sigma_t, sigma_r, rng);
    const Eigen::Vector3d d = q.t - centre.t;
    mean += d / n;
    var += d.cwiseProduct(d) / n;
    angle += SE3Space::rotation_angle(q.q, centre.q) / n;
  }
  EXPECT_LT(mean.norm(), 0.05);
  EXPECT_NEAR(std::sqrt(var.x()), 3 * sigma_t, 0.05);
  EXPECT_NEAR(std::sqrt(var.y()), sigma_t, 0.02);
  EXPECT_NEAR(std::sqrt(var.z()), sigma_t, 0.02);
  // Rotation: a 3-D normal rotation vector of deviation sigma_r has mean length sigma_r sqrt(8 /
  // pi).
  EXPECT_NEAR(angle, sigma_r * std::sqrt(8.0 / std::numbers::pi), 0.01);
}

TEST(GaussianShot, StaysInThePlaneAndInTheBounds) {
  const SE3Space plane(SpaceKind::planar, Bounds{{0, 0, 0}, {1, 1, 0}});
  Rng rng(2);
  for (int i = 0; i < 2000; ++i) {
    const Config q =
        gaussian_shot(plane, plane.planar_config(0.9, 0.5, 0.0), Twist::Ones(), 0.3, 0.5, rng);
    ASSERT_TRUE(plane.satisfies_bounds(q));
    ASSERT_NEAR((q.q * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace tandem
