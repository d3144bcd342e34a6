#include "plan_run.hpp"

#include <stdexcept>

#include "tandem/core/stopwatch.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/runs/portfolio.hpp"

namespace tandem::cli {
namespace {

/// The path as written: simplified (unless asked not to), checked as it reads back from its file.
void finish_path(PlanRun& out, const Problem& problem, bool simplify, MotionValidator& validator) {
  out.path = out.run.path;
  if (simplify) {
    const Stopwatch watch;
    Rng rng(out.spec.settings.seed ^ 0x9e3779b97f4a7c15ULL);
    out.path = simplify_path(std::move(out.path), validator, rng);
    out.simplify_time_s = watch.seconds();
  }
  if (problem.goal_region)
    out.path = cut_at_goal_region(out.path, *problem.goal_region, problem.space);
  out.path = parse_path(format_path(out.path, problem.space), problem.space, "the planned path");
  const PathCheck check = check_path(out.path, validator);
  if (!check.valid)
    throw std::logic_error("the planned path failed its own check: " + check.describe());
}

}  // namespace

PlanRun plan_run(const Problem& problem, const RunArgs& args, bool simplify,
                 const CollisionChecker* prepared) {
  PlanRun out;
  out.spec = make_spec(args, problem);
  // Shown resolved: --threads 0 (the default) is one per core.
  if (!uses_operator(out.spec))
    out.spec.settings.threads = resolve_threads(out.spec);
  CollisionChecker checker =
      prepared != nullptr ? prepared->clone() : CollisionChecker(problem.scene);
  require_valid_endpoints(problem, checker, validation_settings(out.spec.settings));
  out.run = execute_run(problem, out.spec, checker);
  if (out.run.status == PlannerStatus::solved) {
    // The path is simplified and checked the way the planner checked its motions.
    MotionValidator validator(problem.space, checker, validation_settings(out.spec.settings));
    finish_path(out, problem, simplify, validator);
  }
  return out;
}

}  // namespace tandem::cli
