// The operator switch: the simulated operator, a person in the browser or a SpaceMouse has the part.

#include "tandem/operators/operator_switch.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "support/problems.hpp"
#include "support/runs.hpp"
#include "tandem/runs/run.hpp"

namespace tandem {
namespace {

using test::detour_problem;
using test::live_spec;
using ::testing::HasSubstr;

TEST(OperatorSwitch, TakesOverWhereThePartIsAndKeepsItInTheSpace) {
  const Problem problem = detour_problem();
  RunSpec spec = live_spec(1);
  const auto simulated = make_operator(problem, spec, OperatorClock::seconds);
  OperatorSwitch input(problem.space, simulated, problem.start);
  const DeviceReading a = input.read(0.5);
  EXPECT_EQ(a.q_device, simulated->read(0.5).q_device) << "the simulated operator has the part";
  std::string why;
  EXPECT_FALSE(input.select(OperatorInput::spacemouse, &why));
  EXPECT_THAT(why, HasSubstr("spacenavd"));
  ASSERT_TRUE(input.select(OperatorInput::browser));
  EXPECT_EQ(input.read(5.0).q_device, a.q_device) << "the person takes the part where it was";
  Config far = problem.start;
  far.t = {1e6, -1e6, 0.0};
  far.q = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);  // not unit
  input.set_pose(far, 3);
  const DeviceReading b = input.read(5.1);
  EXPECT_TRUE(problem.space.satisfies_bounds(b.q_device)) << "clamped to the bounds";
  EXPECT_NEAR(b.q_device.q.norm(), 1.0, 1e-12);
  EXPECT_EQ(b.input_id, 3u);
  EXPECT_TRUE(input.input_time(3).has_value());
  EXPECT_FALSE(input.input_time(2).has_value());

  OperatorSwitch alone(problem.space, nullptr, problem.start);
  EXPECT_EQ(alone.snapshot().input, OperatorInput::browser);
  EXPECT_EQ(alone.read(1.0).q_device, problem.start) << "without an operator the part waits";
  EXPECT_FALSE(alone.select(OperatorInput::simulated, &why));
}

}  // namespace
}  // namespace tandem
