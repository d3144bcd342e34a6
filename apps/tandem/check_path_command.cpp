// tandem check-path: validate a path file against a problem.

#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/parameter.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_settings.hpp"

namespace tandem::cli {
namespace {

struct CheckArgs {
  ProblemArgs problem;
  std::string path_file;
  /// --validation, --tolerance and --clearance, read as the planners' tunables are.
  PlannerSettings settings;
};

int run_check(const CheckArgs& args) {
  const Problem problem = load_problem(args.problem);
  const Path path = read_path_file(args.path_file, problem.space);
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker, validation_settings(args.settings));
  const PathCheck check = check_path(path, validator);
  if (!check.valid) {
    std::cout << args.path_file << ": invalid at index " << check.index << ": " << check.describe()
              << '\n';
    return 1;
  }
  const bool starts =
      problem.space.distance(path.front(), problem.start) < 1e-6 * problem.space.max_extent();
  const bool ends = problem.goal_region ? problem.goal_region->contains(path.back())
                                        : problem.space.distance(path.back(), problem.goal) <
                                              1e-6 * problem.space.max_extent();
  const char* goal = problem.goal_region ? "in the goal region" : "at the goal";
  std::cout << args.path_file << ": valid: " << path.size() << " states, " << validator.checks()
            << " configurations checked, length " << path_length(problem.space, path) << "; "
            << (starts ? "starts at the start" : "does not start at the start") << ", "
            << (ends ? "ends " : "does not end ") << goal << '\n';
  return 0;
}

}  // namespace

Command add_check_path_command(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  add_problem_args(app, args->problem);
  add_path_file_arg(app, args->path_file);
  for (const char* name : {"validation", "tolerance", "clearance"}) {
    const Param<PlannerSettings>& p = *find_param(planner_parameters(), name);
    app.add_option_function<std::string>(
        p.spec.option(),
        [args, &p](const std::string& text) {
          p.set(args->settings, parse_param_option(p.spec, text));
        },
        std::string(p.spec.help) + " (default: " + format_param(p.get(PlannerSettings{})) + ")");
  }
  app.footer(
      "Checks every state (bounds, collision) and every motion between consecutive states: the "
      "whole continuous motion (exact, the default) or the states at the problem's resolution "
      "(discrete).\nExit 0 if all are valid; 1 and the first invalid index otherwise; 2 for bad "
      "input.");
  return [args] { return run_check(*args); };
}

}  // namespace tandem::cli
