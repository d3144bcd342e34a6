// tandem clearance: how close a path's part comes to the obstacles, over the whole motion.

#include <fstream>
#include <iomanip>
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/error.hpp"
#include "tandem/io/clearance_json.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path_clearance.hpp"

namespace tandem::cli {
namespace {

struct ClearanceArgs {
  ProblemArgs problem;
  std::string path_file;
  double accuracy = 0.01;
  bool json = false;
  std::string csv;
};

/// One row per state, then one per motion: what, where, the certified and the measured minimum.
void write_csv(const std::string& file, const PathClearance& c, const CollisionChecker& checker) {
  std::ofstream out(file);
  if (!out)
    throw InputError(file, "cannot be written");
  out << std::setprecision(17) << "kind,from,to,lower,found,at,obstacle\n";
  for (std::size_t i = 0; i < c.states.size(); ++i) {
    const StateClearance& s = c.states[i];
    out << "state," << i << ',' << i << ',' << s.distance << ',' << s.distance << ",0,"
        << checker.obstacle_name(s.obstacle) << '\n';
  }
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const SegmentClearance& s = c.segments[i];
    out << "motion," << i << ',' << i + 1 << ',' << s.lower << ',' << s.found << ',' << s.at << ','
        << checker.obstacle_name(s.obstacle) << '\n';
  }
}

void print(const ClearanceArgs& args, const PathClearance& c, const CollisionChecker& checker) {
  std::size_t worst = 0;
  for (std::size_t i = 1; i < c.segments.size(); ++i)
    worst = c.segments[i].lower < c.segments[worst].lower ? i : worst;
  std::cout << args.path_file << ": minimum clearance " << c.lower() << " (certified; within "
            << 100 * c.accuracy << "% of the true minimum)";
  if (!c.segments.empty()) {
    const SegmentClearance& s = c.segments[worst];
    std::cout << ", near '" << checker.obstacle_name(s.obstacle) << "' on the motion from state "
              << worst << " to " << worst + 1 << " at " << s.at;
  }
  std::cout << '\n';
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const SegmentClearance& s = c.segments[i];
    std::cout << "  " << i << " -> " << i + 1 << ": " << s.lower << " near '"
              << checker.obstacle_name(s.obstacle) << "'\n";
  }
}

int run_clearance(const ClearanceArgs& args) {
  const Problem problem = load_problem(args.problem);
  const Path path = read_path_file(args.path_file, problem.space);
  CollisionChecker checker(problem.scene);
  const double floor = 1e-9 * problem.space.max_extent();
  const PathClearance c = path_clearance(path, checker, problem.space, args.accuracy, floor);
  if (!args.csv.empty())
    write_csv(args.csv, c, checker);
  if (args.json)
    std::cout << clearance_json(c, checker).dump(2) << '\n';
  else
    print(args, c, checker);
  return 0;
}

}  // namespace

Command add_clearance_command(CLI::App& app) {
  auto args = std::make_shared<ClearanceArgs>();
  add_problem_args(app, args->problem);
  add_path_file_arg(app, args->path_file);
  app.add_option("--accuracy", args->accuracy,
                 "The share of the smallest measured distance by which the certified minimum of "
                 "a motion may fall short of it")
      ->check(CLI::Range(1e-6, 0.5))
      ->capture_default_str();
  app.add_flag("--json", args->json, "Print every state's and motion's clearance as JSON");
  app.add_option("--csv", args->csv, "Also write every state's and motion's clearance here");
  return [args]() { return run_clearance(*args); };
}

}  // namespace tandem::cli
