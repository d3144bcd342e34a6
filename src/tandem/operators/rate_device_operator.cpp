#include "tandem/operators/rate_device_operator.hpp"

#include <algorithm>
#include <stdexcept>

namespace tandem {

RateDeviceOperator::RateDeviceOperator(const SE3Space& space,
                                       std::shared_ptr<const OperatorSource> intent,
                                       HumanLimits limits)
    : space_(space), intent_(std::move(intent)), limits_(limits) {
  if (intent_ == nullptr)
    throw std::invalid_argument("a rate-device operator needs an intent");
  if (!(limits_.device.linear > 0.0) || !(limits_.device.angular > 0.0) ||
      !(limits_.reaction_delay_s >= 0.0) || !(limits_.steering_time_s > 0.0))
    throw std::invalid_argument("human limits must be positive");
}

const Config& RateDeviceOperator::seen(double t) const {
  const double then = t - limits_.reaction_delay_s;
  while (history_.size() > 1 && history_[1].t <= then)
    history_.pop_front();
  return history_.front().q;
}

DeviceReading RateDeviceOperator::read_paced(double t, double pace) const {
  DeviceReading reading = intent_->read_paced(t, pace);
  const Config& want = reading.q_device;
  if (!started_) {
    started_ = true;
    pose_ = want;
    last_t_ = t;
    history_.push_back({t, pose_});
  }
  const double dt = std::max(0.0, t - last_t_);
  last_t_ = t;
  const Config& from = seen(t);
  // Translation: deflection proportional to the way left, saturated at full deflection.
  const Eigen::Vector3d gap = want.t - from.t;
  Eigen::Vector3d v = gap / limits_.steering_time_s;
  if (v.norm() > limits_.device.linear)
    v *= limits_.device.linear / v.norm();
  // Rotation: about the axis of the turn left, likewise.
  Eigen::Quaterniond turn = want.q * from.q.conjugate();
  if (turn.w() < 0.0)
    turn.coeffs() = -turn.coeffs();
  const Eigen::AngleAxisd left(turn.normalized());
  const double w = std::min(left.angle() / limits_.steering_time_s, limits_.device.angular);
  Config next = pose_;
  next.t += v * dt;
  if (w * dt > 0.0)
    next.q = Eigen::Quaterniond(Eigen::AngleAxisd(w * dt, left.axis())) * next.q;
  pose_ = space_.admissible(next);
  history_.push_back({t, pose_});
  reading.q_device = pose_;
  reading.velocity.head<3>() = v;
  reading.velocity.tail<3>() = w * left.axis();
  return reading;
}

std::string RateDeviceOperator::describe() const {
  return intent_->describe() + ", by a person: " + limits_.describe();
}

}  // namespace tandem
