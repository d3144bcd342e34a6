#pragma once
// Where q_device comes from: a simulated operator, a recorded trace (and, later, live devices).
//
// A source is a pure function of operator time (and, for a simulated operator that watches the
// roadmap, of its pace): read(t) gives the same reading for the same t whatever was read before
// and on whichever thread. The determinism of virtual-time runs rests on
// this (the operator state of iteration k can be computed ahead on the operator thread or late on
// the planner thread, with the same result).
//
// Threading: read() is const and may run concurrently on several threads.

#include <limits>
#include <memory>
#include <string>

#include "tandem/interaction/operator_state.hpp"

namespace tandem {

class OperatorSource {
 public:
  virtual ~OperatorSource() = default;
  /// The reading at operator time t >= 0 (seconds, or ticks in virtual time).
  virtual DeviceReading read(double t) const = 0;
  /// The reading at time t of an operator whose progress along its way stands where it would be
  /// at time `pace` (a person who waited for the roadmap, or went back to it, is behind schedule;
  /// see Pacer). The default ignores the pace.
  virtual DeviceReading read_paced(double t, double pace) const {
    (void)pace;
    return read(t);
  }
  /// How far (metric distance) the operator lets q_device get from the roadmap before it waits
  /// and goes back (see Pacer); infinity for a source that does not watch the roadmap (a trace).
  virtual double lead() const { return std::numeric_limits<double>::infinity(); }
  /// How late (operator time) the operator notices what the roadmap does (see Pacer); 0 but for
  /// a simulated person in human time.
  virtual double reaction_delay() const { return 0.0; }
  /// The time after which the reading no longer changes (the end of a guide or a trace), if any.
  virtual double end_time() const = 0;
  virtual std::string describe() const = 0;
};

}  // namespace tandem
