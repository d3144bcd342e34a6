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
  add_take_out_args(command, args.take_out);
}

void add_path_file_arg(CLI::App& command, std::string& path_file) {
  command
      .add_option("PATHFILE", path_file,
                  "A path in OMPL's format (x y z qx qy qz qw, or x y theta)")
      ->required();
}

void add_tessellation_args(CLI::App& command, CadOptions& o, const std::string& group) {
  command
      .add_option("--linear-deflection", o.linear_deflection,
                  "Tessellation: metres between a face and its triangles (0: 0.1% of the "
                  "assembly's bounding-box diagonal)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str()
      ->group(group);
  command
      .add_option("--angular-deflection", o.angular_deflection,
                  "Tessellation: radians between neighbouring triangles on a curved face")
      ->check(CLI::PositiveNumber)
      ->capture_default_str()
      ->group(group);
}

void add_take_out_args(CLI::App& command, TakeOutOptions& o) {
  const char* group = "Taking a part out of a STEP or IGES assembly";
  command
      .add_option("--part", o.part,
                  "The part that moves, by its name or its path in the assembly tree ('tandem "
                  "parts FILE' lists them); the rest of the assembly is the environment, the start "
                  "is where the part sits, the goal the part anywhere outside the assembly's "
                  "bounding box grown by --margin")
      ->group(group);
  command
      .add_option("--margin", o.margin,
                  "Metres between the assembly's bounding box and the part taken out (0: 5% of "
                  "the box's diagonal)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str()
      ->group(group);
  command
      .add_option("--seat-tolerance", o.seat_tolerance,
                  "Metres the part's surface is moved inward, so that it leaves the seat it "
                  "touches; no motion goes deeper into a neighbour (negative: twice the "
                  "linear deflection)")
      ->capture_default_str()
      ->group(group);
  add_tessellation_args(command, o.cad, group);
}

Problem load_problem(const ProblemArgs& args) {
  ProblemLoadOptions options;
  for (const auto& d : args.allowed_dirs)
    options.allowed_dirs.emplace_back(d);
  options.take_out = args.take_out;
  Problem problem = tandem::load_problem(args.problem, options);
  check_hints(problem.hints, problem.source);
  return problem;
}

void require_valid_endpoints(const Problem& problem, CollisionChecker& checker,
                             const ValidationSettings& validation) {
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
    if (validation.clearance > 0.0 && near.distance < validation.clearance) {
      std::ostringstream os;
      os << "the " << what << " is " << near.distance << " from obstacle '"
         << checker.obstacle_name(near.obstacle) << "', closer than --clearance "
         << validation.clearance;
      throw InputError(problem.source, os.str());
    }
  }
}

}  // namespace tandem::cli
