#pragma once
// One planning run, as the command line and the experiments describe it: which planner mode, its
// settings, and who the operator is. execute_run() builds the collision checker, the operator (a
// simulated one following the problem's guide, or a recorded trace) and its feed, runs the planner,
// and returns the outcome. Deterministic for a given spec in virtual time.

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tandem/operators/operator_profile.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

/// The planner modes of the papers' experiments.
enum class PlannerMode : std::uint8_t {
  birrt,                ///< the computer alone (Kuffner & LaValle's RRT-Connect)
  rrt,                  ///< single-tree RRT, the computer alone
  interactive,          ///< authority sharing (Blin et al. 2016, Algorithm 1)
  interactive_contact,  ///< authority sharing with contact sampling (Algorithm 3)
  irrt,                 ///< the I-RRT (Taix & Flavigne 2011)
};
std::string_view to_string(PlannerMode mode);
std::optional<PlannerMode> parse_planner_mode(std::string_view name);
const std::vector<std::string>& planner_mode_names();
bool is_interactive(PlannerMode mode);

struct RunSpec {
  PlannerMode mode = PlannerMode::birrt;
  PlannerSettings settings;
  /// "experienced" / "inexperienced" (following the problem's guide), or "trace:FILE".
  std::string operator_name = "experienced";
  /// Multiplies the profile's speed (1 = the profile's own).
  double operator_speed = 1.0;
  std::uint64_t operator_seed = 1;
  /// Virtual time: the operator's state changes every this many planner iterations.
  std::uint64_t operator_period = 10;
  double time_limit = 60.0;
  std::uint64_t max_iterations = UINT64_MAX;
  /// Stops the run (status interrupted) when set to true by another thread.
  const std::atomic<bool>* stop = nullptr;
};

struct RunOutcome {
  PlannerStatus status = PlannerStatus::running;
  PlannerStats stats;
  Path path;  ///< the planner's path (not simplified); empty unless solved
  double path_length = 0.0;
  std::string operator_description;
  /// Operator updates at which a simulated operator found the roadmap beyond its lead and went
  /// back.
  std::uint64_t operator_waits = 0;
  double range = 0.0;
  /// tree_digest() of the planner's trees when it stopped: same spec, same digest (for runs that
  /// end by solving or by an iteration limit; a time limit stops at a machine-dependent point).
  std::uint64_t tree_digest = 0;
};

/// The planner a mode runs: "birrt", "rrt" or "irrt" (make_planner's names).
std::string_view planner_name(PlannerMode mode);
/// The spec's settings as its mode means them: the computer alone has alpha = 1 and no contact,
/// interactive has no contact, interactive-contact has it.
PlannerSettings mode_settings(PlannerMode mode, const PlannerSettings& settings);

/// Throws InputError for a spec the problem cannot run (an interactive mode without a guide or
/// trace, a trace that cannot be read, a start or goal that is not valid).
RunOutcome execute_run(const Problem& problem, const RunSpec& spec);
/// The same with a checker built for the problem's scene (its counters keep counting).
RunOutcome execute_run(const Problem& problem, const RunSpec& spec, CollisionChecker& checker);

/// The operator source of a spec: a guide follower or a trace player, on the given clock
/// (planner iterations for runs in virtual time, seconds for live sessions). Throws InputError for
/// a trace recorded on the other clock.
std::shared_ptr<const OperatorSource> make_operator(const Problem& problem, const RunSpec& spec,
                                                    OperatorClock clock = OperatorClock::ticks);

}  // namespace tandem
