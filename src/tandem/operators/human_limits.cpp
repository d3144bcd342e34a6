#include "tandem/operators/human_limits.hpp"

#include <numbers>
#include <sstream>

namespace tandem {

RateDeviceScale spacemouse_scale(const SE3Space& space) {
  return {0.1 * space.translation_extent(), std::numbers::pi / 2.0};
}

HumanLimits human_limits(const SE3Space& space) {
  HumanLimits limits;
  limits.device = spacemouse_scale(space);
  return limits;
}

std::string HumanLimits::describe() const {
  std::ostringstream o;
  o << "rate device (at most " << device.linear << " units/s, "
    << device.angular * 180.0 / std::numbers::pi << " deg/s), reaction " << reaction_delay_s
    << " s, steering " << steering_time_s << " s";
  return o.str();
}

}  // namespace tandem
