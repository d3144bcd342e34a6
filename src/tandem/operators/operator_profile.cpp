#include "tandem/operators/operator_profile.hpp"

#include <numbers>
#include <stdexcept>

namespace tandem {

OperatorProfile operator_profile(std::string_view name, const SE3Space& space,
                                 OperatorClock clock) {
  const double D = space.max_extent();
  const double diagonal = space.translation_extent();
  constexpr double kDeg = std::numbers::pi / 180.0;
  // One unit of operator time: an iteration (virtual time) or a second. A virtual-time operator
  // crosses the space in a few thousand iterations; a wall-clock one in a few tens of seconds.
  const double per_unit = clock == OperatorClock::ticks ? 1.0 / 1000.0 : 1.0 / 4.0;
  OperatorProfile p;
  p.name = std::string(name);
  // Poor fine motion: even an experienced operator strays by about 1% of the scene's diagonal (10
  // cm in a 10 m scene) and 3 degrees; an inexperienced one by three times as much.
  if (name == "experienced") {
    p.speed = D * per_unit / 4.0;
    p.tremor_translation = 0.01 * diagonal;
    p.tremor_rotation = 3.0 * kDeg;
    p.tremor_frequency = 8.0 * per_unit;
    // Keeps the object a quarter of a planner step (range = 0.2 D) ahead of the roadmap.
    p.lead = 0.05 * D;
  } else if (name == "inexperienced") {
    p.speed = D * per_unit / 16.0;
    p.tremor_translation = 0.03 * diagonal;
    p.tremor_rotation = 8.0 * kDeg;
    p.tremor_frequency = 5.0 * per_unit;
    p.pause_rate = 4.0 / D;
    p.pause_duration = 2.0 / per_unit;
    p.backtrack_share = 0.3;
    p.backtrack_distance = 0.05 * D;
    // Watches the roadmap less closely: lets the object get half a planner step ahead.
    p.lead = 0.1 * D;
  } else {
    throw std::invalid_argument("unknown operator profile '" + std::string(name) + "'");
  }
  return p;
}

const std::vector<std::string>& operator_profile_names() {
  static const std::vector<std::string> kNames = {"experienced", "inexperienced"};
  return kNames;
}

}  // namespace tandem
