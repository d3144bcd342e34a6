#pragma once
// How a simulated operator keeps pace with the roadmap it watches.
//
// The papers' operator moves the object "through the visualization of the roadmap": a person who
// sees the trees lag behind does not run on to the goal, but waits and goes back to where the
// roadmap is. A Pacer models this with the operator's own clock, its pace: the pace follows
// operator time while the roadmap (the tree it carries from the start) is within the operator's
// lead of q_device, and runs backward (the operator retraces its way, at its own speed) while it
// is not; the source is then read at that pace (OperatorSource::read_paced). What the operator
// looks at is only the roadmap, as a person sees it on the screen: never a solution. A person in
// human time notices it `reaction_delay` late: the pace then follows what the roadmap was then.
//
// Deterministic: the pace is a function of the sequence of (time, distance) observations.
// Threading: not thread-safe; one per operator.

#include <cmath>
#include <deque>
#include <utility>

namespace tandem {

class Pacer {
 public:
  /// `lead`: metric distance; infinity makes the pace equal the time (an operator who never looks).
  explicit Pacer(double lead, double reaction_delay = 0.0)
      : lead_(lead), reaction_delay_(reaction_delay) {}

  /// Advances to operator time t (non-decreasing), given the distance from the operator's last
  /// q_device to the nearest roadmap node, and returns the pace.
  double advance(double t, double roadmap_distance) {
    const double dt = t - time_;
    time_ = t;
    const double seen = noticed(t, roadmap_distance);
    if (!std::isfinite(lead_)) {
      pace_ = t;
    } else if (dt > 0.0) {
      pace_ = seen <= lead_ ? pace_ + dt : std::fmax(0.0, pace_ - dt);
      if (seen > lead_) {
        ++waits_;
        waited_ += dt;
      }
    }
    return pace_;
  }

  double pace() const { return pace_; }
  double lead() const { return lead_; }
  /// Observations at which the operator found the roadmap too far and went back.
  unsigned long long waits() const { return waits_; }
  /// Operator time spent waiting for the roadmap (going back to it).
  double waited() const { return waited_; }

 private:
  /// The distance observed reaction_delay_ before t (the first one, before that).
  double noticed(double t, double distance) {
    if (reaction_delay_ <= 0.0)
      return distance;
    seen_.emplace_back(t, distance);
    while (seen_.size() > 1 && seen_[1].first <= t - reaction_delay_)
      seen_.pop_front();
    return seen_.front().second;
  }

  double lead_;
  double reaction_delay_;
  double time_ = 0.0;
  double pace_ = 0.0;
  unsigned long long waits_ = 0;
  double waited_ = 0.0;
  std::deque<std::pair<double, double>> seen_;  ///< (time, distance) over the reaction delay
};

}  // namespace tandem
