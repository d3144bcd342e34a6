#pragma once
// One planning run (a RunSpec, see run_spec.hpp) carried out: execute_run() builds the collision
// checker, the operator (a simulated one following the problem's guide, or a recorded trace) and
// its feed, runs the planner — or, for a planner that plans alone on several threads, a portfolio
// of them (portfolio.hpp) — and returns the outcome. Deterministic for a given spec (and thread
// count) in virtual time.

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/interaction/operator_source.hpp"
#include "tandem/operators/operator_profile.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct RunOutcome {
  PlannerStatus status = PlannerStatus::running;
  PlannerStats stats;
  Path path;  ///< the planner's path (not simplified); empty unless solved
  double path_length = 0.0;
  std::string operator_description;
  /// Operator updates at which a simulated operator found the roadmap beyond its lead and went
  /// back.
  std::uint64_t operator_waits = 0;
  /// Seconds a simulated person in human time spent going back to the roadmap (execute_wall_run;
  /// 0 in virtual time).
  double operator_wait_s = 0.0;
  double range = 0.0;
  /// tree_digest() of the planner's trees when it stopped: same spec, same digest (for runs that
  /// end by solving or by an iteration limit; a time limit stops at a machine-dependent point).
  std::uint64_t tree_digest = 0;
  /// Searches run at once (portfolio.hpp); 1 for the planners that take an operator.
  unsigned threads = 1;
  /// The portfolio's member whose search this is (0 for one thread).
  unsigned member = 0;
  /// That member's planner (the spec's mode, but "birrt" or "rrt" for birrt+rrt: portfolio.hpp).
  std::string member_planner;
};

/// Throws InputError for a spec the problem cannot run (a planner that takes an operator on a
/// problem without a guide, a trace that cannot be read). An invalid start or goal is an outcome
/// (status invalid_start, invalid_goal), not an error.
RunOutcome execute_run(const Problem& problem, const RunSpec& spec);
/// The same with a checker built for the problem's scene (its counters keep counting, but for a
/// portfolio's, whose members query clones of it).
RunOutcome execute_run(const Problem& problem, const RunSpec& spec, CollisionChecker& checker);

/// What a planner that stopped with `status` has to show: its statistics, trees and path.
RunOutcome planner_outcome(const Problem& problem, const Planner& planner, PlannerStatus status);

/// The operator source of a spec: a guide follower or a trace player, on the given clock
/// (planner iterations for runs in virtual time, seconds for live sessions and runs in human time).
/// On the wall clock, a guide follower is a person's intent, done through a rate device within
/// human limits (RateDeviceOperator); a trace in seconds was recorded from a person and plays as
/// it is. Throws InputError for a trace recorded on the other clock.
std::shared_ptr<const OperatorSource> make_operator(const Problem& problem, const RunSpec& spec,
                                                    OperatorClock clock = OperatorClock::ticks);

}  // namespace tandem
