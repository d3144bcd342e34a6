#include "tandem/space/se3_space.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

const SE3Space& space3() {
  static const SE3Space s(SpaceKind::se3, Bounds{{-10, -5, -2}, {10, 5, 2}});
  return s;
}

/// Configurations built from small integers, so rapidcheck can shrink a counterexample.
rc::Gen<Config> gen_config() {
  return rc::gen::apply(
      [](int x, int y, int z, int a, int b, int c, int d, bool flip) {
        Config q;
        q.t = Eigen::Vector3d(x / 100.0, y / 100.0, z / 100.0);
        Eigen::Vector4d v(a, b, c, d);
        if (v.norm() == 0.0)
          v = Eigen::Vector4d(0, 0, 0, 1);
        v.normalize();
        if (flip)
          v = -v;
        q.q = Eigen::Quaterniond(v[3], v[0], v[1], v[2]);
        return q;
      },
      rc::gen::inRange(-1000, 1000), rc::gen::inRange(-500, 500), rc::gen::inRange(-200, 200),
      rc::gen::inRange(-100, 100), rc::gen::inRange(-100, 100), rc::gen::inRange(-100, 100),
      rc::gen::inRange(-100, 100), rc::gen::arbitrary<bool>());
}

RC_GTEST_PROP(SE3Metric, IsZeroOnTheDiagonalAndNonNegative, ()) {
  const Config a = *gen_config();
  const Config b = *gen_config();
  RC_ASSERT(space3().distance(a, a) < 1e-12);
  RC_ASSERT(space3().distance(a, b) >= 0.0);
}

RC_GTEST_PROP(SE3Metric, IsSymmetric, ()) {
  const Config a = *gen_config();
  const Config b = *gen_config();
  RC_ASSERT(space3().distance(a, b) == space3().distance(b, a));
}

RC_GTEST_PROP(SE3Metric, SatisfiesTheTriangleInequality, ()) {
  const Config a = *gen_config();
  const Config b = *gen_config();
  const Config c = *gen_config();
  RC_ASSERT(space3().distance(a, c) <= space3().distance(a, b) + space3().distance(b, c) + 1e-9);
}

RC_GTEST_PROP(SE3Metric, TreatsQAndMinusQAlike, ()) {
  Config a = *gen_config();
  Config b = *gen_config();
  Config a_neg = a;
  a_neg.q.coeffs() = -a.q.coeffs();
  RC_ASSERT(space3().distance(a, a_neg) < 1e-7);
  RC_ASSERT(std::abs(space3().distance(a, b) - space3().distance(a_neg, b)) < 1e-9);
}

RC_GTEST_PROP(SE3Metric, EqualsOmplSE3Distance, ()) {
  // OMPL: |dt| + acos(|<q1, q2>|) (SE3StateSpace with unit weights; SO3StateSpace::distance).
  const Config a = *gen_config();
  const Config b = *gen_config();
  const double dot = std::min(1.0, std::abs(a.q.coeffs().dot(b.q.coeffs())));
  const double ompl = (a.t - b.t).norm() + std::acos(dot);
  RC_ASSERT(std::abs(space3().distance(a, b) - ompl) < 1e-6);
}

RC_GTEST_PROP(SE3Interpolation, HitsBothEnds, ()) {
  const Config a = *gen_config();
  const Config b = *gen_config();
  RC_ASSERT(space3().interpolate(a, b, 0.0).t.isApprox(a.t));
  RC_ASSERT(space3().distance(space3().interpolate(a, b, 0.0), a) < 1e-7);
  RC_ASSERT(space3().distance(space3().interpolate(a, b, 1.0), b) < 1e-7);
}

RC_GTEST_PROP(SE3Interpolation, MovesAlongAGeodesic, ()) {
  // d(a, x(s)) = s d(a, b) and d(x(s), b) = (1 - s) d(a, b): translation and rotation both progress
  // uniformly along the shortest arc.
  const Config a = *gen_config();
  const Config b = *gen_config();
  const double s = *rc::gen::inRange(0, 1001) / 1000.0;
  const Config x = space3().interpolate(a, b, s);
  const double d = space3().distance(a, b);
  RC_ASSERT(std::abs(space3().distance(a, x) - s * d) < 1e-6 * (1.0 + d));
  RC_ASSERT(std::abs(space3().distance(x, b) - (1.0 - s) * d) < 1e-6 * (1.0 + d));
  RC_ASSERT(std::abs(x.q.norm() - 1.0) < 1e-12);
}

RC_GTEST_PROP(SE3Interpolation, StepsAreTheSameInBothDirections, ()) {
  const Config a = *gen_config();
  const Config b = *gen_config();
  const unsigned n = static_cast<unsigned>(*rc::gen::inRange(1, 200));
  const unsigned k = static_cast<unsigned>(*rc::gen::inRange(0, static_cast<int>(n) + 1));
  RC_ASSERT(space3().step(a, b, k, n) == space3().step(b, a, n - k, n));
}

TEST(SE3Space, ExtentRangeAndResolutionFollowOmpl) {
  const SE3Space& s = space3();
  const double diagonal = std::sqrt(20.0 * 20.0 + 10.0 * 10.0 + 4.0 * 4.0);
  EXPECT_DOUBLE_EQ(s.translation_extent(), diagonal);
  EXPECT_DOUBLE_EQ(s.max_extent(), diagonal + std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(s.default_range(), 0.2 * (diagonal + std::numbers::pi / 2));
  EXPECT_DOUBLE_EQ(s.translation_step(), 0.01 * diagonal);
  // 1% of pi/2 in OMPL's half-angle distance is 1% of pi in rotation angle.
  EXPECT_DOUBLE_EQ(s.rotation_step(), 0.01 * std::numbers::pi);
}

TEST(SE3Space, SegmentCountIsTheLargerOfTranslationAndRotation) {
  const SE3Space& s = space3();
  Config a, b;
  b.t = Eigen::Vector3d(10.5 * s.translation_step(), 0, 0);
  EXPECT_EQ(s.segment_count(a, b), 11u);
  b.q = Eigen::Quaterniond(Eigen::AngleAxisd(30.5 * s.rotation_step(), Eigen::Vector3d::UnitY()));
  EXPECT_EQ(s.segment_count(a, b), 31u);
  EXPECT_EQ(s.segment_count(a, a), 0u);
}

TEST(SE3Space, RotationAngleIsAccurateNearZeroAndPi) {
  const Eigen::Quaterniond id = Eigen::Quaterniond::Identity();
  for (double angle : {1e-9, 1e-6, 0.3, 3.0, std::numbers::pi - 1e-7}) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()));
    EXPECT_NEAR(SE3Space::rotation_angle(id, q), angle, 1e-12 * std::max(1.0, angle)) << angle;
  }
}

TEST(SE3Space, RotationLowerBoundNeverExceedsTheAngleAndStaysWithinTenPercent) {
  // The k-d tree skips a point when this bound reaches its current best: it must never exceed the
  // angle as computed, at any angle (near 0 the two agree to third order), with either sign of
  // either quaternion and with quaternions a few rounding steps from unit length.
  Rng rng(5);
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  auto check = [](const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    const double angle = SE3Space::rotation_angle(a, b);
    const double bound = SE3Space::rotation_lower_bound(a, b);
    ASSERT_GE(bound, 0.0);
    ASSERT_LE(bound, angle) << angle;
    ASSERT_GE(bound, 0.9 * angle) << angle;
  };
  for (double angle : {0.0, 1e-300, 1e-15, 1e-9, 1e-6, 1e-3, 0.3, 3.0, std::numbers::pi - 1e-9,
                       std::numbers::pi}) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis));
    const Eigen::Quaterniond id = Eigen::Quaterniond::Identity();
    check(id, q);
    check(q, id);
    check(Eigen::Quaterniond(-q.coeffs()), id);
  }
  for (int i = 0; i < 100000; ++i) {
    const Eigen::Quaterniond a = space3().sample_uniform(rng).q;
    // Near a (down to rounding), anywhere, and products that are unit only up to rounding.
    const double scale = std::pow(10.0, -16.0 * rng.uniform01());
    const Eigen::Quaterniond near(
        Eigen::AngleAxisd(scale, space3().sample_uniform(rng).t.normalized()));
    check(a, near * a);
    check(a, space3().sample_uniform(rng).q);
    check(a * near * near * near, a);
  }
}

TEST(SE3Space, UniformSamplesStayInBounds) {
  Rng rng(7);
  for (int i = 0; i < 20000; ++i) {
    const Config q = space3().sample_uniform(rng);
    ASSERT_TRUE(space3().satisfies_bounds(q));
    ASSERT_NEAR(q.q.norm(), 1.0, 1e-12);
  }
}

TEST(SE3Space, UniformSamplesAreUniformOnSO3) {
  // Under the Haar measure the rotation angle has density (1 - cos t) / pi on [0, pi]:
  // CDF F(t) = (t - sin t) / pi, mean pi/2 + 2/pi. Kolmogorov-Smirnov at n = 20000: the 0.1%
  // critical value is 1.95 / sqrt(n) = 0.0138.
  Rng rng(11);
  const int n = 20000;
  std::vector<double> angles;
  double mean = 0.0;
  for (int i = 0; i < n; ++i) {
    angles.push_back(
        SE3Space::rotation_angle(Eigen::Quaterniond::Identity(), space3().sample_uniform(rng).q));
    mean += angles.back() / n;
  }
  EXPECT_NEAR(mean, std::numbers::pi / 2 + 2 / std::numbers::pi, 0.02);
  std::sort(angles.begin(), angles.end());
  double ks = 0.0;
  for (int i = 0; i < n; ++i) {
    const double F =
        (angles[static_cast<std::size_t>(i)] - std::sin(angles[static_cast<std::size_t>(i)])) /
        std::numbers::pi;
    ks = std::max({ks, std::abs(F - static_cast<double>(i) / n),
                   std::abs(F - static_cast<double>(i + 1) / n)});
  }
  EXPECT_LT(ks, 0.0138);
  // The rotation axis is uniform too: the mean of the rotated x axis is near 0.
  Eigen::Vector3d axis_mean = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i)
    axis_mean += space3().sample_uniform(rng).q * Eigen::Vector3d::UnitX() / n;
  EXPECT_LT(axis_mean.norm(), 0.03);
}

TEST(PlanarSpace, SamplesRotateAboutZOnlyAndKeepZ) {
  const SE3Space s(SpaceKind::planar, Bounds{{-5, -5, 0.25}, {5, 5, 0.25}});
  Rng rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Config q = s.sample_uniform(rng);
    ASSERT_DOUBLE_EQ(q.t.z(), 0.25);
    ASSERT_NEAR((q.q * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  }
}

TEST(PlanarSpace, MetricEqualsOmplSE2) {
  // OMPL's SE2StateSpace: |dxy| + 0.5 |dtheta| (SO2 weight 0.5, shortest way round).
  const SE3Space s(SpaceKind::planar, Bounds{{-5, -5, 0}, {5, 5, 0}});
  const Config a = s.planar_config(1, 2, 3.0);
  const Config b = s.planar_config(-1, 0, -3.0);
  const double dtheta = 2 * std::numbers::pi - 6.0;
  EXPECT_NEAR(s.distance(a, b), std::sqrt(8.0) + 0.5 * dtheta, 1e-12);
  EXPECT_NEAR(s.max_extent(), std::sqrt(200.0) + 0.5 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(SE3Space::yaw(s.interpolate(a, b, 0.5).q), std::numbers::pi, 1e-9);
}

TEST(SE3Space, RejectsInvalidArguments) {
  auto error = [](auto make) { return test::error_message<InputError>(make); };
  EXPECT_THAT(
      error([] {
        return SE3Space(SpaceKind::se3, Bounds{{1, 0, 0}, {0, 1, 1}});
      }),
      HasSubstr("bounds: invalid workspace bounds: min (1 0 0) must not exceed max (0 1 1)"));
  EXPECT_THAT(error([] {
                return SE3Space(SpaceKind::se3, Bounds{{0, 0, 0}, {1, 1, 1}}, {}, 0.0);
              }),
              HasSubstr("resolution: must be in (0, 1), got 0"));
  EXPECT_THAT(error([] {
                return SE3Space(SpaceKind::se3, Bounds{{0, 0, 0}, {1, 1, 1}}, {}, 1.5);
              }),
              HasSubstr("resolution: must be in (0, 1), got 1.5"));
  EXPECT_THAT(
      error([] {
        return SE3Space(SpaceKind::se3, Bounds{{0, 0, 0}, {1, 1, 1}}, MetricWeights{0.0, 0.5});
      }),
      HasSubstr("weights: translation weight must be > 0 and rotation weight >= 0"));
  EXPECT_THAT(error([] {
                return SE3Space(SpaceKind::se3, Bounds{{0, 0, 0}, {0, 0, 0}});
              }),
              HasSubstr("bounds: the workspace bounds have zero extent"));
}

}  // namespace
}  // namespace tandem
