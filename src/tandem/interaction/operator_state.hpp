#pragma once
// What the operator thread publishes for the planner: the papers' q_device and what the human loop
// computes from it (Blin et al. 2016, section IV-A: "reading the interactive device data and
// integrating positions ... cycling through obstacles to find the nearest one ... computing R and
// δ").
//
// A value type; it crosses threads by copy (see LatestValue).

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/interaction/contact_frame.hpp"
#include "tandem/space/config.hpp"
#include "tandem/space/twist.hpp"

namespace tandem {

/// What a device (or a simulated operator) gives at one instant.
struct DeviceReading {
  Config q_device;
  Twist velocity = Twist::Zero();
  std::uint32_t buttons = 0;
  /// The live input event this reading came from (0: none); for measuring input-to-tree latency,
  /// not journaled.
  std::uint64_t input_id = 0;
};

struct OperatorState {
  std::uint64_t sequence = 0;  ///< 1, 2, ... in publication order
  double time = 0.0;           ///< operator time: seconds, or planner iterations in virtual time
  double pace = 0.0;           ///< where the operator is along its way, in time (see Pacer)
  DeviceReading device;
  NearestObstacle nearest;            ///< the object at q_device against the scene
  std::optional<ContactFrame> frame;  ///< the tangent plane there, when the object does not touch
};

}  // namespace tandem
