#pragma once
// The limits of a person who moves the part in real time with a 6D mouse: what a wall-clock
// simulated operator (RateDeviceOperator) cannot do faster than a person.
//
// - The device is a rate device, as a SpaceMouse is used: its deflection, at most full, is a
//   velocity of the part. At full deflection the part crosses a tenth of the scene's bounds
//   diagonal in a second and turns a quarter turn in a second (the speeds the live session gives
//   a real SpaceMouse, OperatorSwitch). A person cannot move the part faster than that.
// - A person reacts to what they see about a quarter of a second late (visual reaction time is
//   200-300 ms): they steer toward where they want the part from where they saw it then, and
//   notice that the roadmap lags behind only that late (Pacer).
// - A person steers smoothly: the deflection is proportional to the way left to where they want
//   the part, full at steering_time_s worth of full speed; the hand thus closes most of a small
//   gap in about that time, and moves a large one at full speed.
//
// Amounts scale with the scene (its bounds' diagonal) as the viewer's view does.

#include <string>

#include "tandem/space/se3_space.hpp"

namespace tandem {

/// A rate device at full deflection: scene units per second, radians per second.
struct RateDeviceScale {
  double linear = 0.0;
  double angular = 0.0;
};

/// A SpaceMouse as tandem scales it for a scene (see above).
RateDeviceScale spacemouse_scale(const SE3Space& space);

struct HumanLimits {
  RateDeviceScale device;
  double reaction_delay_s = 0.25;
  double steering_time_s = 0.4;

  std::string describe() const;
};

/// The limits above for a scene.
HumanLimits human_limits(const SE3Space& space);

}  // namespace tandem
