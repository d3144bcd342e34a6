// The simulated operator that follows a guide.

#include "tandem/operators/guide_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"

namespace tandem {
namespace {

const SE3Space& space() {
  return test::room_space();
}

std::vector<Config> guide() {
  std::vector<Config> k(3);
  k[0].t = {-4, 0, 1};
  k[1].t = {0, 3, 1};
  k[1].q = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  k[2].t = {4, 0, 1};
  return k;
}

TEST(GuideFollower, WalksTheGuideFromStartToEnd) {
  const auto profile = operator_profile("experienced", space(), OperatorClock::ticks);
  const GuideFollower op(space(), guide(), profile, 1);
  EXPECT_NEAR(op.end_time(), op.guide_length() / profile.speed, 1e-6);  // no pauses
  EXPECT_LT((op.read(0).q_device.t - guide()[0].t).norm(), 3 * profile.tremor_translation);
  EXPECT_LT((op.read(op.end_time() + 100).q_device.t - guide()[2].t).norm(),
            3 * profile.tremor_translation);
  // Halfway in time is halfway along the guide.
  EXPECT_NEAR(op.progress(op.end_time() / 2), op.guide_length() / 2, 1e-9);
  // Its velocity follows the guide.
  const DeviceReading r = op.read(op.end_time() / 4);
  EXPECT_GT(r.velocity.head<3>().norm(), 0.5 * profile.speed);
}

TEST(GuideFollower, IsAPureFunctionOfTime) {
  const auto profile = operator_profile("inexperienced", space(), OperatorClock::ticks);
  const GuideFollower a(space(), guide(), profile, 7), b(space(), guide(), profile, 7);
  for (double t : {5000.0, 10.0, 123456.0, 10.0, 77.5}) {
    EXPECT_TRUE(a.read(t).q_device == b.read(t).q_device);
    EXPECT_TRUE(a.read(t).q_device == a.read(t).q_device);
  }
  const GuideFollower c(space(), guide(), profile, 8);
  EXPECT_FALSE(a.read(5000).q_device == c.read(5000).q_device);
}

TEST(GuideFollower, InexperiencedOperatorsAreSlowNoisyAndHesitate) {
  const auto fast = operator_profile("experienced", space(), OperatorClock::ticks);
  const auto slow = operator_profile("inexperienced", space(), OperatorClock::ticks);
  EXPECT_LT(slow.speed, fast.speed);
  EXPECT_GT(slow.tremor_translation, fast.tremor_translation);
  const GuideFollower op(space(), guide(), slow, 3);
  EXPECT_GT(op.end_time(), op.guide_length() / slow.speed);  // pauses and back-ups take time
  int pauses = 0, backups = 0;
  double previous = op.progress(0);
  const double dt = 10.0;
  for (double t = dt; t < op.end_time(); t += dt) {
    const double s = op.progress(t);
    pauses += s == previous;
    backups += s < previous;
    previous = s;
  }
  EXPECT_GT(pauses, 0);
  EXPECT_GT(backups, 0);
  // Tremor: off the guide, but within a few amplitudes.
  double off = 0.0;
  for (double t = 0; t < op.end_time(); t += 97.0) {
    off = std::max(off, (op.read(t).q_device.t - op.guide_pose(op.progress(t)).t).norm());
  }
  EXPECT_GT(off, 0.2 * slow.tremor_translation);
  EXPECT_LT(off, 2.0 * std::sqrt(3.0) * slow.tremor_translation);
}

TEST(GuideFollower, StaysInTheBounds) {
  std::vector<Config> k = guide();
  k[1].t = {0, 4.99, 1.99};
  const GuideFollower op(space(), k,
                         operator_profile("inexperienced", space(), OperatorClock::ticks), 2);
  for (double t = 0; t < op.end_time(); t += 50.0)
    ASSERT_TRUE(space().satisfies_bounds(op.read(t).q_device));
}

}  // namespace
}  // namespace tandem
