#include "tandem/runs/run.hpp"

#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/operators/rate_device_operator.hpp"
#include "tandem/operators/trace.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/portfolio.hpp"

namespace tandem {

std::shared_ptr<const OperatorSource> make_operator(const Problem& problem, const RunSpec& spec,
                                                    OperatorClock clock) {
  const std::string& name = spec.operator_name;
  if (name.rfind("trace:", 0) == 0) {
    Trace trace = read_trace_file(name.substr(6));
    if (trace.clock != clock) {
      throw InputError(name.substr(6), clock == OperatorClock::ticks
                                           ? "a trace in seconds cannot drive a virtual-time run "
                                             "(record it in ticks)"
                                           : "a trace in ticks (virtual time) cannot drive a live "
                                             "session (record it in seconds)");
    }
    return std::make_shared<TracePlayer>(problem.space, std::move(trace));
  }
  if (problem.guide.empty()) {
    throw InputError(problem.source,
                     "the problem has no [guide] for a simulated operator; give a trace instead");
  }
  OperatorProfile profile;
  try {
    profile = operator_profile(name, problem.space, clock);
  } catch (const std::invalid_argument&) {
    throw InputError("--operator",
                     "unknown operator '" + name + "' (experienced, inexperienced, or trace:FILE)");
  }
  if (!(spec.operator_speed > 0.0))
    throw InputError("--operator-speed", "must be positive");
  profile.speed *= spec.operator_speed;
  auto follower =
      std::make_shared<GuideFollower>(problem.space, problem.guide, profile, spec.operator_seed);
  if (clock == OperatorClock::ticks)
    return follower;
  return std::make_shared<RateDeviceOperator>(problem.space, std::move(follower),
                                              human_limits(problem.space));
}

RunOutcome execute_run(const Problem& problem, const RunSpec& spec) {
  CollisionChecker checker(problem.scene);
  return execute_run(problem, spec, checker);
}

RunOutcome planner_outcome(const Problem& problem, const Planner& planner, PlannerStatus status) {
  RunOutcome outcome;
  outcome.status = status;
  outcome.stats = planner.stats();
  outcome.tree_digest = tree_digest(planner.trees());
  outcome.range = planner.range();
  if (status == PlannerStatus::solved) {
    outcome.path = planner.solution();
    outcome.path_length = path_length(problem.space, outcome.path);
  }
  return outcome;
}

RunOutcome execute_run(const Problem& problem, const RunSpec& spec, CollisionChecker& checker) {
  if (!uses_operator(spec)) {
    const unsigned threads = resolve_threads(spec);
    if (threads > 1)
      return run_portfolio(problem, spec, checker, threads);
  }
  MotionValidator validator(problem.space, checker);

  std::unique_ptr<VirtualTimeFeed> feed;
  Interaction interaction;
  std::string operator_description;
  if (uses_operator(spec)) {
    auto source = make_operator(problem, spec);
    operator_description = source->describe();
    feed = std::make_unique<VirtualTimeFeed>(OperatorModel(checker, std::move(source)),
                                             spec.operator_period);
    interaction.feed = feed.get();
  }
  auto planner = make_planner(spec.mode, validator, problem.start, problem.goal, spec.settings,
                              interaction.feed != nullptr ? &interaction : nullptr);
  Termination termination;
  termination.time_limit_s = spec.time_limit;
  termination.max_iterations = spec.max_iterations;
  termination.stop = spec.stop;
  RunOutcome outcome = planner_outcome(problem, *planner, planner->solve(termination));
  outcome.member_planner = member_planner(spec.mode, 0);
  outcome.operator_description = std::move(operator_description);
  if (feed != nullptr)
    outcome.operator_waits = feed->operator_waits();
  return outcome;
}

}  // namespace tandem
