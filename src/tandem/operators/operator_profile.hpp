#pragma once
// How a simulated operator moves: the 2011 paper's simulated user (section VII) made richer.
//
// "A person has a good global idea of the way and poor fine motion": a simulated operator follows a
// coarse guide (a few hand-placed keyframes) at some speed, with tremor, and, if inexperienced,
// slowly, with pauses and back-ups. Like the papers' operators, who work "through the
// visualization of the roadmap", it watches the roadmap: it does not run ahead of it by more than
// its lead, and goes back along its guide to where the roadmap is when it has (see Pacer). It
// never sees a solution. Amounts scale with the scene (its maximum extent D and the bounds'
// diagonal), so one profile fits every scene.

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/space/se3_space.hpp"

namespace tandem {

/// The operator's clock: planner iterations (virtual time, deterministic) or wall-clock seconds.
enum class OperatorClock { ticks, seconds };

struct OperatorProfile {
  std::string name;
  double speed = 0.0;               ///< metric distance along the guide per unit of operator time
  double tremor_translation = 0.0;  ///< amplitude, length units
  double tremor_rotation = 0.0;     ///< amplitude, radians
  double tremor_frequency = 0.0;    ///< cycles per unit of operator time (centre of the band)
  double pause_rate = 0.0;          ///< expected pauses per unit of metric distance along the guide
  double pause_duration = 0.0;      ///< operator time per pause
  double backtrack_share = 0.0;     ///< share of pauses that start by backing up
  double backtrack_distance = 0.0;  ///< metric distance backed up
  /// How far (metric distance) the operator lets the object get from the nearest roadmap node
  /// before it stops following its guide and goes back along it; infinity: it never looks.
  double lead = std::numeric_limits<double>::infinity();
};

/// "experienced" (fast, precise) or "inexperienced" (slow, noisy, hesitating), scaled to the space
/// and the clock. Throws std::invalid_argument for another name.
OperatorProfile operator_profile(std::string_view name, const SE3Space& space, OperatorClock clock);

const std::vector<std::string>& operator_profile_names();

}  // namespace tandem
