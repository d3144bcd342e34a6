#pragma once
// How a simulated operator keeps pace with the roadmap it watches.
//
// The papers' operator moves the object "through the visualization of the roadmap": a person who
// sees the trees lag behind does not run on to the goal, but waits and goes back to where the
// roadmap is. A Pacer models this with the operator's own clock, its pace: the pace follows
// operator time while the roadmap (the tree it carries from the start) is within the operator's
// lead of q_device, and runs backward (the operator retraces its way, at its own speed) while it
// is not; the source is then read at that pace (OperatorSource::read_paced). What the operator
// looks at is only the roadmap, as a person sees it on the screen: never a solution.
//
// Deterministic: the pace is a function of the sequence of (time, distance) observations.
// Threading: not thread-safe; one per operator.

#include <cmath>

namespace tandem {

class Pacer {
 public:
  /// `lead`: metric distance; infinity makes the pace equal the time (an operator who never looks).
  explicit Pacer(double lead) : lead_(lead) {}

  /// Advances to operator time t (non-decreasing), given the distance from the operator's last
  /// q_device to the nearest roadmap node, and returns the pace.
  double advance(double t, double roadmap_distance) {
    const double dt = t - time_;
    time_ = t;
    if (!std::isfinite(lead_)) {
      pace_ = t;
    } else if (dt > 0.0) {
      pace_ = roadmap_distance <= lead_ ? pace_ + dt : std::fmax(0.0, pace_ - dt);
      if (roadmap_distance > lead_)
        ++waits_;
    }
    return pace_;
  }

  double pace() const { return pace_; }
  double lead() const { return lead_; }
  /// Observations at which the operator found the roadmap too far and went back.
  unsigned long long waits() const { return waits_; }

 private:
  double lead_;
  double time_ = 0.0;
  double pace_ = 0.0;
  unsigned long long waits_ = 0;
};

}  // namespace tandem
