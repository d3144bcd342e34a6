#pragma once
// An adaptive step per node, for the planners that plan alone.
//
// A fixed step (OMPL's range, 0.2 x the space's extent) suits open space and fails in clutter:
// inside the alpha puzzle or a narrow slot almost every extension of that length collides, and
// the tree stops growing where it must. A smaller fixed step crawls through open space instead
// (measured: the best fixed step is 3-4% of the extent on alpha-1.5, Twistycool and Apartment and
// 0.2 on cubicles). So each node has its own step:
//   - a blocked extension from a node (nothing added) halves that node's step, down to
//     `floor` x range;
//   - a new node starts at twice its parent's step, at most range.
// A tree thus takes long steps where its extensions succeed and short ones where they collide,
// like the dynamic domain of Yershova et al. (ICRA 2005), which shrinks where a node may be
// extended instead of how far.
//
// The floor itself is lowered as a search goes on without a path (relax()): halved once the
// search has made kRelaxFrom collision queries, again at four times as many, and so on, down to
// kLeastFloor x range. The solved problems of the README's table need 4 000 to 41 000 queries per
// run at their median, and plan as before; a tight puzzle that holds a search for millions gets
// ever finer steps. Measured on alpha-1.2 (two threads, 60 s, seeds 1-4): a fixed floor of 1/8
// solved 0 of 3, 1/16 none of 4, 1/32 three, 1/128 two; but 1/32 from the start made alpha-1.5
// 5.6 times and Apartment 3.1 times slower, hence a floor that falls with the search's work.
//
// Deterministic: a function of the extensions' outcomes and of the search's query count.
// Threading: one per tree (one thread).

#include <algorithm>
#include <cstdint>
#include <vector>

#include "tandem/planning/planner_settings.hpp"
#include "tandem/planning/tree.hpp"

namespace tandem {

/// The floor a planner's settings give its AdaptiveStep: settings.adaptive_step for the classic
/// extension; 1 (a fixed step) for last-valid, which stops a blocked extension at the obstacle
/// already (measured on environment 1, which the papers plan last-valid: 6 of 6 seeds solved with
/// a median of 1.9 s at a fixed step, 5 of 6 and 18 s adaptive; classic extension there: 4 of 6
/// adaptive, 0 of 6 fixed, 60 s limit).
inline double adaptive_floor(const PlannerSettings& settings) {
  return settings.extend == ExtendMode::classic ? settings.adaptive_step : 1.0;
}

class AdaptiveStep {
 public:
  /// Queries of a search before its floor is first halved; each later halving comes after
  /// kRelaxGrowth times as many.
  static constexpr double kRelaxFrom = 100000.0;
  static constexpr double kRelaxGrowth = 4.0;
  /// The lowest floor relax() goes to, as a share of range (a lower `floor` given stays).
  static constexpr double kLeastFloor = 1.0 / 128.0;

  /// Steps in [floor x range, range]; floor >= 1 keeps every step at range.
  AdaptiveStep(double range, double floor) : range_(range), min_(std::min(floor, 1.0) * range) {}

  bool adapts() const { return min_ < range_; }

  /// The search has made `queries` collision queries: lowers the floor on the schedule above (a
  /// fixed step, floor >= 1, stays fixed).
  void relax(std::uint64_t queries) {
    while (adapts() && static_cast<double>(queries) >= relax_at_) {
      relax_at_ *= kRelaxGrowth;
      min_ = std::min(min_, std::max(0.5 * min_, kLeastFloor * range_));
    }
  }

  /// The current floor, as a share of range.
  double floor() const { return min_ / range_; }

  /// The step of an extension from node n.
  double step(NodeId n) const { return n < step_.size() ? step_[n] : range_; }

  /// An extension from n added nothing.
  void blocked(NodeId n) {
    if (!adapts())
      return;  // every step is range: nothing to record
    reach(n);
    step_[n] = std::max(min_, 0.5 * step_[n]);
  }

  /// `node` was added as a child of `parent`.
  void added(NodeId node, NodeId parent) {
    if (!adapts())
      return;
    const double s = std::min(range_, 2.0 * step(parent));
    reach(node);
    step_[node] = s;
  }

 private:
  void reach(NodeId n) {
    if (n >= step_.size())
      step_.resize(static_cast<std::size_t>(n) + 1, range_);
  }

  double range_;
  double min_;
  double relax_at_ = kRelaxFrom;
  std::vector<double> step_;  ///< by node; nodes past its end have range
};

}  // namespace tandem
