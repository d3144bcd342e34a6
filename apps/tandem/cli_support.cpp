#include "cli_support.hpp"

#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/runs/run_spec.hpp"

namespace tandem::cli {

void add_problem_args(CLI::App& command, ProblemArgs& args) {
  command
      .add_option(
          "PROBLEM", args.problem,
          "An OMPL.app problem (.cfg), a tandem scenario (.toml), or a built-in scene's name")
      ->required();
  command.add_option(
      "--allow-dir", args.allowed_dirs,
      "A folder the problem may read meshes and URDFs from, besides its own (repeatable)");
}

Problem load_problem(const ProblemArgs& args) {
  ProblemLoadOptions options;
  for (const auto& d : args.allowed_dirs)
    options.allowed_dirs.emplace_back(d);
  Problem problem = tandem::load_problem(args.problem, options);
  check_hints(problem.hints, problem.source);
  return problem;
}

void require_valid_endpoints(const Problem& problem, CollisionChecker& checker) {
  const std::pair<const char*, const Config*> ends[] = {{"start", &problem.start},
                                                        {"goal", &problem.goal}};
  for (const auto& [what, q] : ends) {
    if (!problem.space.satisfies_bounds(*q)) {
      std::ostringstream os;
      os << "the " << what << " (" << q->t.transpose() << ") is outside the workspace bounds";
      throw InputError(problem.source, os.str());
    }
    const NearestObstacle near = checker.nearest_obstacle(*q);
    if (near.in_collision || !checker.is_collision_free(*q)) {
      throw InputError(problem.source, std::string("the ") + what +
                                           " is in collision with obstacle '" +
                                           checker.obstacle_name(near.obstacle) + "'");
    }
  }
}

}  // namespace tandem::cli
