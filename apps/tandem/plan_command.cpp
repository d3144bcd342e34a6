// tandem plan: solve a problem with an automatic planner.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/io/text.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/render/svg_render.hpp"

namespace tandem::cli {
namespace {

struct PlanArgs {
  ProblemArgs problem;
  std::optional<std::string> planner;
  std::optional<std::uint64_t> seed;
  std::optional<double> time_limit;
  std::optional<double> range;
  std::optional<double> goal_bias;
  std::optional<std::string> extend;
  std::string out;
  std::string svg;
  bool json = false;
  bool no_simplify = false;
};

constexpr double kDefaultTimeLimit = 60.0;

/// Fails before planning, not after, when an output file cannot be written: no work is lost.
void require_writable(const std::string& file) {
  if (file.empty())
    return;
  const std::filesystem::path p = std::filesystem::absolute(file);
  std::error_code ec;
  if (std::filesystem::is_directory(p, ec))
    throw InputError(file, "is a folder");
  if (!std::filesystem::is_directory(p.parent_path(), ec)) {
    throw InputError(file, "cannot be written: no folder " + p.parent_path().string());
  }
  if (access(p.parent_path().c_str(), W_OK) != 0) {
    throw InputError(file, "cannot be written: the folder is not writable");
  }
}

int run_plan(const PlanArgs& args) {
  require_writable(args.out);
  require_writable(args.svg);
  const Problem problem = load_problem(args.problem);
  const std::string planner_name = args.planner.value_or(problem.hints.planner.value_or("birrt"));

  PlannerSettings settings;
  settings.seed = args.seed.value_or(problem.hints.seed.value_or(1));
  if (args.range) {
    settings.range = *args.range;
  } else if (auto it = problem.hints.range.find(planner_name); it != problem.hints.range.end()) {
    settings.range = it->second;
  }
  settings.goal_bias =
      args.goal_bias.value_or(problem.hints.goal_bias.value_or(settings.goal_bias));
  settings.extend =
      *parse_extend_mode(args.extend.value_or(problem.hints.extend.value_or("classic")));
  const double time_limit =
      args.time_limit.value_or(problem.hints.time_limit.value_or(kDefaultTimeLimit));

  CollisionChecker checker(problem.scene);
  require_valid_endpoints(problem, checker);
  MotionValidator validator(problem.space, checker);
  auto planner = make_planner(planner_name, validator, problem.start, problem.goal, settings);

  Termination termination;
  termination.time_limit_s = time_limit;
  const PlannerStatus status = planner->solve(termination);
  const PlannerStats stats = planner->stats();
  const bool solved = status == PlannerStatus::solved;

  Path path;
  double raw_length = 0.0;
  double simplify_time = 0.0;
  if (solved) {
    path = planner->solution();
    raw_length = path_length(problem.space, path);
    if (!args.no_simplify) {
      const Stopwatch watch;
      Rng rng(settings.seed ^ 0x9e3779b97f4a7c15ULL);
      path = simplify_path(std::move(path), validator, rng);
      simplify_time = watch.seconds();
    }
    // What is written is what is checked: the path as it reads back from its file.
    path = parse_path(format_path(path, problem.space), problem.space, "the planned path");
    const PathCheck check = check_path(path, validator);
    if (!check.valid) {
      throw std::logic_error("the planned path failed its own check: " + check.describe());
    }
    if (!args.out.empty())
      write_path_file(args.out, path, problem.space);
  }
  if (!args.svg.empty())
    write_file_atomically(args.svg, render_svg(problem, path));

  if (args.json) {
    nlohmann::json j;
    j["problem"] = problem.name;
    j["source"] = problem.source;
    j["planner"] = planner_name;
    j["status"] = std::string(to_string(status));
    j["solved"] = solved;
    j["seed"] = settings.seed;
    j["range"] = planner->range();
    j["extend"] = std::string(to_string(settings.extend));
    j["time_limit_s"] = time_limit;
    j["time_s"] = stats.time_s;
    j["iterations"] = stats.iterations;
    j["nodes"] = stats.nodes;
    j["edges"] = stats.edges;
    j["collision_checks"] = stats.collision_checks;
    j["path_length"] =
        solved ? nlohmann::json(path_length(problem.space, path)) : nlohmann::json(nullptr);
    j["raw_path_length"] = solved ? nlohmann::json(raw_length) : nlohmann::json(nullptr);
    j["path_states"] = path.size();
    j["simplify_time_s"] = simplify_time;
    j["out"] = args.out.empty() ? nlohmann::json(nullptr) : nlohmann::json(args.out);
    std::cout << j.dump() << '\n';
  } else {
    std::cout << problem.name << ": "
              << (solved ? "solved" : "not solved (" + std::string(to_string(status)) + ")")
              << " by " << planner_name << " in " << stats.time_s << " s, " << stats.iterations
              << " iterations, " << stats.nodes << " nodes, " << stats.collision_checks
              << " collision checks (seed " << settings.seed << ")\n";
    if (solved) {
      std::cout << "path: " << path.size() << " states, length " << path_length(problem.space, path)
                << " (before simplification " << raw_length << ")";
      if (!args.out.empty())
        std::cout << ", written to " << args.out;
      std::cout << '\n';
    }
    if (!args.svg.empty())
      std::cout << "picture: " << args.svg << '\n';
  }
  return solved ? 0 : 1;
}

}  // namespace

Command add_plan_command(CLI::App& app) {
  auto args = std::make_shared<PlanArgs>();
  add_problem_args(app, args->problem);
  app.add_option("--planner", args->planner, "Planner: birrt (RRT-Connect, default) or rrt")
      ->check(CLI::IsMember(planner_names()));
  app.add_option("--seed", args->seed,
                 "Random seed (default: the problem's, else 1); same seed, same path")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--time-limit", args->time_limit,
                 "Seconds before giving up (default: the problem's, else 60)")
      ->check(CLI::PositiveNumber);
  app.add_option("--range", args->range,
                 "Longest motion added per extension (default: the problem's, else 0.2 x the "
                 "space's extent)")
      ->check(CLI::PositiveNumber);
  app.add_option("--goal-bias", args->goal_bias,
                 "RRT's probability of extending toward the goal (default 0.05)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option(
         "--extend", args->extend,
         "How a tree grows toward a target it cannot reach: classic (all or nothing; the default "
         "unless the problem says otherwise) or last-valid (keep the last valid configuration, the "
         "papers' Add_Tree)")
      ->check(CLI::IsMember({"classic", "last-valid"}));
  app.add_option("--out", args->out, "Write the path here, in OMPL's path format");
  app.add_option("--svg", args->svg, "Draw the problem and the path into this SVG file");
  app.add_flag("--json", args->json, "Print one JSON object with the run's figures");
  app.add_flag("--no-simplify", args->no_simplify, "Keep the path as the planner found it");
  app.footer(
      "The path is simplified (shortcuts), checked as read back from its file, then written.\n"
      "--json prints: problem, source, planner, status, solved, seed, range, extend, time_limit_s, "
      "time_s,\niterations, nodes, edges, collision_checks, path_length, raw_path_length, "
      "path_states, "
      "simplify_time_s, out.\nExit 0 if solved; 1 if not solved within the time limit; 2 for bad "
      "input "
      "(including a start or\ngoal outside the bounds or in collision).");
  return [args] { return run_plan(*args); };
}

}  // namespace tandem::cli
