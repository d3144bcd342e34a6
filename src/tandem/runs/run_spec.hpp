#pragma once
// One planning run, as the command line, problem files and experiments describe it: which planner
// (a registry name), its settings, and who the operator is — and the one way every surface sets a
// tunable of it (set_tunable), with the ranges the tables declare.

#include <atomic>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/core/parameter.hpp"
#include "tandem/planning/planner_settings.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct RunSpec {
  /// The planner: a name of planner_registry() ("birrt", "interactive-contact", ...).
  std::string mode = "birrt";
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
  /// Where the route leads a portfolio (portfolio.hpp): the work after which member 0 gives its
  /// helper thread's core to member 1. About 80 ms of queries at 40 ns a unit.
  std::uint64_t helper_work = 2'000'000;
  /// Stops the run (status interrupted) when set to true by another thread.
  const std::atomic<bool>* stop = nullptr;
};

/// The declarations of the run's own tunables: the simulated operator's (operator, operator_speed,
/// operator_period).
const ParamTable<RunSpec>& operator_parameters();

/// Every tunable of a run, of every family (planner, interaction, operator), in that order, bound
/// to RunSpec.
const ParamTable<RunSpec>& run_tunables();

/// A spec for `mode` with its defaults (the planner's preset) and the problem's own settings
/// (range, extend, goal bias, seed, time limit, and any other tunable its [planner] section sets).
/// Throws InputError for an unknown mode or a bad value in the problem.
RunSpec default_spec(std::string_view mode, const ProblemPlannerHints& hints);

/// Checks what a problem file says about planning (its planner's name, its tunables' names and
/// values); throws InputError naming the file and line. Every command that loads a problem calls it.
void check_hints(const ProblemPlannerHints& hints, const std::string& source);

/// Sets tunable `name` to `value`, or throws InputError(where, fault) for an unknown name or a
/// value outside the declared range. `where` names the option or the file and line.
void set_tunable(RunSpec& spec, std::string_view name, const ParamValue& value,
                 const std::string& where);

/// Throws InputError(where, ...) when the spec's planner does not use tunable `name`.
void require_used(const RunSpec& spec, std::string_view name, const std::string& where);

/// Whether the spec's planner takes an operator.
bool uses_operator(const RunSpec& spec);

/// The tunables the spec's planner reads, by name, with their values.
std::map<std::string, ParamValue> used_tunables(const RunSpec& spec);

}  // namespace tandem
