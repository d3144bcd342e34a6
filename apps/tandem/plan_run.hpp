#pragma once
// One `tandem plan`, as a function: the run the options describe, the path simplified (unless
// asked not to), cut where it enters a goal region, and checked as it reads back from its file.
// The command line and the Python module (python/) both plan through it, so that the same seed
// gives the same path from either.

#include "run_options.hpp"
#include "tandem/runs/run.hpp"

namespace tandem::cli {

struct PlanRun {
  RunSpec spec;  ///< with --threads 0 resolved to the core count (planners without an operator)
  RunOutcome run;
  Path path;  ///< empty unless solved
  double simplify_time_s = 0.0;
};

/// Throws InputError for bad options, or a start or goal outside the bounds or in collision.
/// `prepared`, if given, is a checker of this problem's scene whose clone the run uses: what it
/// has built (the distance grid) is not built again.
PlanRun plan_run(const Problem& problem, const RunArgs& args, bool simplify,
                 const CollisionChecker* prepared = nullptr);

}  // namespace tandem::cli
