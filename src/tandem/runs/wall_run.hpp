#pragma once
// A run in human time: the papers' two loops on two threads, as a live session runs them (see
// session/live_session.hpp), for experiments. The operator thread runs the simulated person
// (make_operator on the wall clock: a guide follower driven through a rate device with human
// limits, RateDeviceOperator) and finds the nearest obstacle; the planner thread plans with the
// latest state it published, and the person, watching the roadmap, waits for it. Times are
// wall-clock seconds of the person's time, from the planner's start.
//
// Not reproducible bit for bit (the threads' timing decides which state each iteration sees), as
// no live session is; a live session's journal is what replays one. A planner that plans alone
// runs as execute_run runs it (its time limit is wall-clock already), on spec.settings.threads.

#include "tandem/runs/run.hpp"

namespace tandem {

/// Throws InputError as execute_run() does.
RunOutcome execute_wall_run(const Problem& problem, const RunSpec& spec, CollisionChecker& checker);

}  // namespace tandem
