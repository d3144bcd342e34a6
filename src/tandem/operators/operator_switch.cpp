#include "tandem/operators/operator_switch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tandem/operators/human_limits.hpp"

namespace tandem {
std::string_view to_string(OperatorInput input) {
  switch (input) {
    case OperatorInput::simulated:
      return "simulated";
    case OperatorInput::browser:
      return "browser";
    case OperatorInput::spacemouse:
      return "spacemouse";
  }
  return "?";
}

std::optional<OperatorInput> parse_operator_input(std::string_view name) {
  for (OperatorInput i :
       {OperatorInput::simulated, OperatorInput::browser, OperatorInput::spacemouse}) {
    if (name == to_string(i))
      return i;
  }
  return std::nullopt;
}

OperatorSwitch::OperatorSwitch(const SE3Space& space,
                               std::shared_ptr<const OperatorSource> simulated, const Config& start,
                               std::unique_ptr<SpaceNav> spacenav, std::string no_spacenav)
    : space_(space),
      simulated_(std::move(simulated)),
      spacenav_(std::move(spacenav)),
      no_spacenav_(std::move(no_spacenav)),
      input_(simulated_ != nullptr ? OperatorInput::simulated : OperatorInput::browser),
      held_(start),
      linear_speed_(spacemouse_scale(space).linear),
      angular_speed_(spacemouse_scale(space).angular) {}

DeviceReading OperatorSwitch::read_paced(double t, double pace) const {
  OperatorInput input;
  DeviceReading reading;
  double linear_speed, angular_speed;
  {
    const std::lock_guard lock(mutex_);
    input = input_;
    reading.q_device = held_;
    reading.input_id = held_input_;
    linear_speed = linear_speed_;
    angular_speed = angular_speed_;
  }
  const double dt = std::clamp(t - last_t_, 0.0, 0.1);
  last_t_ = t;
  if (input == OperatorInput::browser)
    return reading;
  if (input == OperatorInput::simulated) {
    reading = simulated_->read_paced(t, pace);
  } else {
    // Rate control, as a 6D mouse is used: the deflection is a velocity of the part, in the
    // world frame (spacenavd's y up is the scene's z up; its z toward the user is -y).
    const SpaceNavMotion& m = spacenav_->poll();
    const Eigen::Vector3d v(m[0], -m[2], m[1]);
    const Eigen::Vector3d w(m[3], -m[5], m[4]);
    Config q = reading.q_device;
    q.t += linear_speed * dt * v;
    const double angle = angular_speed * dt * w.norm();
    if (angle > 0.0)
      q.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized())) * q.q;
    reading.q_device = space_.admissible(q);
    reading.velocity.head<3>() = linear_speed * v;
    reading.velocity.tail<3>() = angular_speed * w;
    reading.buttons = spacenav_->buttons();
    reading.input_id = 0;
  }
  // Where the part is, for the next input to take over from.
  const std::lock_guard lock(mutex_);
  if (input_ == input)
    held_ = reading.q_device;
  return reading;
}

double OperatorSwitch::lead() const {
  return simulated_ != nullptr ? simulated_->lead() : std::numeric_limits<double>::infinity();
}

double OperatorSwitch::reaction_delay() const {
  return simulated_ != nullptr ? simulated_->reaction_delay() : 0.0;
}

double OperatorSwitch::end_time() const {
  return std::numeric_limits<double>::infinity();
}

std::string OperatorSwitch::describe() const {
  std::string d = "live: ";
  d += simulated_ != nullptr ? simulated_->describe() + ", browser" : std::string("browser");
  if (spacenav_ != nullptr)
    d += ", " + spacenav_->name();
  return d;
}

bool OperatorSwitch::select(OperatorInput input, std::string* why) {
  if (input == OperatorInput::simulated && simulated_ == nullptr) {
    if (why != nullptr)
      *why = "this session has no simulated operator";
    return false;
  }
  if (input == OperatorInput::spacemouse && spacenav_ == nullptr) {
    if (why != nullptr)
      *why = "no SpaceMouse: spacenavd was not running when the session started";
    return false;
  }
  const std::lock_guard lock(mutex_);
  input_ = input;
  return true;
}

void OperatorSwitch::set_pose(const Config& q, std::uint64_t input_id) {
  const Config pose = space_.admissible(q);
  const std::lock_guard lock(mutex_);
  input_ = OperatorInput::browser;
  held_ = pose;
  held_input_ = input_id;
  held_input_time_ = std::chrono::steady_clock::now();
}

std::optional<std::chrono::steady_clock::time_point> OperatorSwitch::input_time(
    std::uint64_t input_id) const {
  const std::lock_guard lock(mutex_);
  if (input_id == 0 || input_id != held_input_)
    return std::nullopt;
  return held_input_time_;
}

void OperatorSwitch::set_spacemouse_speed(double linear, double angular) {
  const std::lock_guard lock(mutex_);
  linear_speed_ = linear;
  angular_speed_ = angular;
}

OperatorSwitch::Snapshot OperatorSwitch::snapshot() const {
  Snapshot s;
  const std::lock_guard lock(mutex_);
  s.input = input_;
  s.simulated_available = simulated_ != nullptr;
  s.spacemouse_available = spacenav_ != nullptr;
  s.spacemouse_status = spacenav_ != nullptr ? spacenav_->name() : no_spacenav_;
  return s;
}

}  // namespace tandem
