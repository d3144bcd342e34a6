#include "tandem/interaction/operator_model.hpp"

namespace tandem {

OperatorModel::OperatorModel(const CollisionChecker& checker,
                             std::shared_ptr<const OperatorSource> source)
    : checker_(checker.clone()), source_(std::move(source)) {}

OperatorState OperatorModel::compute(double t, double pace, std::uint64_t sequence) {
  return observe(source_->read_paced(t, pace), t, pace, sequence);
}

OperatorState OperatorModel::observe(const DeviceReading& reading, double t, double pace,
                                     std::uint64_t sequence) {
  OperatorState s;
  s.sequence = sequence;
  s.time = t;
  s.pace = pace;
  s.device = reading;
  s.nearest = checker_.nearest_obstacle(s.device.q_device);
  s.frame = find_local_frame(s.nearest, s.device.q_device);
  return s;
}

}  // namespace tandem
