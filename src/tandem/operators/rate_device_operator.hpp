#pragma once
// A simulated person in human time: what another simulated operator (its intent, e.g. a
// GuideFollower on the wall clock) wants, done through a 6D mouse by a person with human limits
// (HumanLimits): a rate device, a reaction delay, smooth steering.
//
// Each reading, the person looks at where the part was reaction_delay_s ago, deflects the device
// toward where they want it now (proportionally, saturated at full deflection; translation and
// rotation separately) and the part moves at that velocity for the time since the last reading.
// The part thus never moves faster than the device allows, lags behind a fast intent, and
// overshoots a little when the intent stops, as a person's hand does.
//
// Unlike most sources, this one has a state (the part's pose, what the person saw): read_paced()
// integrates from the previous reading, so it is not a pure function of time. It drives live,
// wall-clock runs only, whose journal records what the planner saw.
//
// Threading: read()/read_paced() on one thread only (the operator thread).

#include <deque>
#include <memory>

#include "tandem/interaction/operator_source.hpp"
#include "tandem/operators/human_limits.hpp"

namespace tandem {

class RateDeviceOperator final : public OperatorSource {
 public:
  RateDeviceOperator(const SE3Space& space, std::shared_ptr<const OperatorSource> intent,
                     HumanLimits limits);

  DeviceReading read(double t) const override { return read_paced(t, t); }
  DeviceReading read_paced(double t, double pace) const override;
  double lead() const override { return intent_->lead(); }
  double reaction_delay() const override { return limits_.reaction_delay_s; }
  double end_time() const override { return intent_->end_time(); }
  std::string describe() const override;

  const HumanLimits& limits() const { return limits_; }

 private:
  struct Seen {
    double t;
    Config q;
  };
  /// Where the part was reaction_delay_s before t, as the person saw it.
  const Config& seen(double t) const;

  const SE3Space& space_;
  std::shared_ptr<const OperatorSource> intent_;
  HumanLimits limits_;
  // The operator thread's state.
  mutable bool started_ = false;
  mutable double last_t_ = 0.0;
  mutable Config pose_;
  mutable std::deque<Seen> history_;  ///< the part's poses over the last reaction delay
};

}  // namespace tandem
