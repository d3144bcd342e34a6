#pragma once
// Where q_device comes from: a simulated operator, a recorded trace (and, later, live devices).
//
// A source is a pure function of operator time: read(t) gives the same reading for the same t
// whatever was read before and on whichever thread. The determinism of virtual-time runs rests on
// this (the operator state of iteration k can be computed ahead on the operator thread or late on
// the planner thread, with the same result).
//
// Threading: read() is const and may run concurrently on several threads.

#include <memory>
#include <string>

#include "tandem/interaction/operator_state.hpp"

namespace tandem {

class OperatorSource {
 public:
  virtual ~OperatorSource() = default;
  /// The reading at operator time t >= 0 (seconds, or ticks in virtual time).
  virtual DeviceReading read(double t) const = 0;
  /// The time after which the reading no longer changes (the end of a guide or a trace), if any.
  virtual double end_time() const = 0;
  virtual std::string describe() const = 0;
};

}  // namespace tandem
