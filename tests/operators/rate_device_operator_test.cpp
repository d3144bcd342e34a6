// A simulated person in human time: an intent done through a rate device within human limits.

#include "tandem/operators/rate_device_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"

namespace tandem {
namespace {

const SE3Space& space() {
  return test::room_space();
}

/// An intent that holds `from` until `t0`, then `to`.
class StepIntent final : public OperatorSource {
 public:
  StepIntent(Config from, Config to, double t0) : from_(from), to_(to), t0_(t0) {}
  DeviceReading read(double t) const override {
    DeviceReading r;
    r.q_device = t < t0_ ? from_ : to_;
    return r;
  }
  double end_time() const override { return t0_; }
  std::string describe() const override { return "step"; }

 private:
  Config from_, to_;
  double t0_;
};

TEST(RateDeviceOperator, NeverMovesThePartFasterThanTheDeviceAllowsAndGetsThere) {
  Config from, to;
  from.t = {-4, 0, 1};
  to.t = {4, 2, 1};
  to.q = Eigen::Quaterniond(Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, 1, 0).normalized()));
  const HumanLimits limits = human_limits(space());
  const RateDeviceOperator person(space(), std::make_shared<StepIntent>(from, to, 0.5), limits);
  const Config start = person.read(0.0).q_device;
  double max_speed = 0.0, max_turn_rate = 0.0;
  Config previous = start;
  const double dt = 1e-3;
  for (int k = 1; k <= 20000; ++k) {
    const Config q = person.read(k * dt).q_device;
    max_speed = std::max(max_speed, (q.t - previous.t).norm() / dt);
    max_turn_rate = std::max(max_turn_rate, SE3Space::rotation_angle(q.q, previous.q) / dt);
    previous = q;
  }
  // The intent jumped at 0.5 s; the part went at the device's full speed, no faster.
  EXPECT_LE(max_speed, limits.device.linear * (1 + 1e-9));
  EXPECT_GT(max_speed, 0.99 * limits.device.linear);
  EXPECT_LE(max_turn_rate, limits.device.angular * (1 + 1e-6));
  EXPECT_GT(max_turn_rate, 0.99 * limits.device.angular);
  // 8.2 m at full speed takes 8.2 / linear seconds; after 20 s the part is where the person wants.
  EXPECT_LT((previous.t - to.t).norm(), 1e-3);
  EXPECT_LT(SE3Space::rotation_angle(previous.q, to.q), 1e-3);
}

/// The largest distance the part went past the target along x, reading every millisecond.
double overshoot_along_x(const RateDeviceOperator& person, double target_x, double seconds) {
  double farthest = -1e9;
  for (int k = 0; k * 1e-3 <= seconds; ++k)
    farthest = std::max(farthest, person.read(k * 1e-3).q_device.t.x() - target_x);
  return farthest;
}

TEST(RateDeviceOperator, APersonWhoSeesLateOvershootsALittleAndSettles) {
  Config from, to;
  from.t = {0, 0, 1};
  to.t = {0.2, 0, 1};  // a small move: proportional steering, not full deflection
  HumanLimits limits = human_limits(space());
  limits.reaction_delay_s = 0.0;
  const RateDeviceOperator sharp(space(), std::make_shared<StepIntent>(from, to, 0.5), limits);
  EXPECT_LE(overshoot_along_x(sharp, 0.2, 5.0), 1e-12);  // seen at once: no overshoot

  limits.reaction_delay_s = 0.25;
  const RateDeviceOperator late(space(), std::make_shared<StepIntent>(from, to, 0.5), limits);
  const double past = overshoot_along_x(late, 0.2, 5.0);
  EXPECT_GT(past, 0.002);  // steering on what it saw a quarter second ago, it goes past
  EXPECT_LT(past, 0.05);
  EXPECT_NEAR(late.read(10.0).q_device.t.x(), 0.2, 1e-3);  // and settles
  EXPECT_EQ(late.reaction_delay(), 0.25);
}

TEST(RateDeviceOperator, KeepsThePartInsideTheBounds) {
  Config from, to;
  from.t = {0, 0, 1};
  to.t = {100, 0, 1};
  const RateDeviceOperator person(space(), std::make_shared<StepIntent>(from, to, 0.5),
                                  human_limits(space()));
  for (int k = 0; k <= 400; ++k)
    EXPECT_TRUE(space().satisfies_bounds(person.read(k * 0.25).q_device));
  EXPECT_NE(person.describe().find("rate device"), std::string::npos);
}

}  // namespace
}  // namespace tandem
