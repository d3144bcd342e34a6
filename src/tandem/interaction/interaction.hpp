#pragma once
// The human loop as a planner sees it: the operator's state (through an OperatorFeed), the live
// tunables, and, for the I-RRT, the guidance force it sends back to the device.

#include <cstdint>

#include "tandem/interaction/interaction_settings.hpp"
#include "tandem/interaction/latest_value.hpp"
#include "tandem/interaction/operator_feed.hpp"
#include "tandem/space/twist.hpp"

namespace tandem {

/// The guidance pseudo-force F_a the I-RRT sends back to the device (2011, section V-A): from the
/// user's position toward the labelled centre of mass of the p nearest nodes. Linear part in scene
/// units, angular part a rotation vector in radians.
struct Guidance {
  std::uint64_t iteration = 0;
  Twist force = Twist::Zero();
};

/// What an interactive planner is connected to. The feed is required; parameters and guidance are
/// optional (without parameters the planner's own InteractionSettings hold throughout).
struct Interaction {
  OperatorFeed* feed = nullptr;
  InteractionParameters* parameters = nullptr;
  LatestValue<Guidance>* guidance = nullptr;
};

}  // namespace tandem
