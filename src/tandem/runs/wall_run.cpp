#include "tandem/runs/wall_run.hpp"

#include "tandem/interaction/operator_thread.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

/// The operator thread's rate, as a live session's (LiveOptions).
constexpr double kOperatorRateHz = 1000.0;

}  // namespace

RunOutcome execute_wall_run(const Problem& problem, const RunSpec& spec,
                            CollisionChecker& checker) {
  if (!uses_operator(spec))
    return execute_run(problem, spec, checker);
  MotionValidator validator(problem.space, checker);
  auto source = make_operator(problem, spec, OperatorClock::seconds);
  LatestValue<OperatorState> channel;
  LatestValue<double> roadmap_distance;
  LiveFeed feed(channel, &roadmap_distance, /*keep_record=*/false);
  Interaction interaction;
  interaction.feed = &feed;
  auto planner =
      make_planner(spec.mode, validator, problem.start, problem.goal, spec.settings, &interaction);
  OperatorThread person(OperatorModel(checker, source), channel, kOperatorRateHz,
                        &roadmap_distance);
  // The planner starts with the person's first state in hand, as in a live session.
  person.wait_for_first_state();
  Termination termination;
  termination.time_limit_s = spec.time_limit;
  termination.max_iterations = spec.max_iterations;
  termination.stop = spec.stop;
  const PlannerStatus status = planner->solve(termination);
  person.stop();
  RunOutcome outcome = planner_outcome(problem, *planner, status);
  outcome.operator_description = source->describe();
  outcome.operator_waits = person.waits();
  outcome.operator_wait_s = person.waited_s();
  return outcome;
}

}  // namespace tandem
