// tandem plan: solve a problem with the computer alone or with a (simulated) operator.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "run_options.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/experiments/run.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/io/text.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/render/svg_render.hpp"

namespace tandem::cli {
namespace {

struct PlanArgs {
  RunArgs run;
  // Output.
  std::string out;
  std::string svg;
  bool json = false;
  bool no_simplify = false;
};

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

nlohmann::json sources_json(const PlannerStats& stats) {
  nlohmann::json j;
  for (std::size_t k = 0; k < kNodeSources; ++k) {
    j[std::string(to_string(static_cast<NodeSource>(k)))] = stats.nodes_by_source[k];
  }
  return j;
}

int run_plan(const PlanArgs& args) {
  require_writable(args.out);
  require_writable(args.svg);
  const Problem problem = load_problem(args.run.problem);
  const RunSpec spec = make_spec(args.run, problem);

  CollisionChecker checker(problem.scene);
  require_valid_endpoints(problem, checker);
  const RunOutcome run = execute_run(problem, spec, checker);
  const PlannerStats& stats = run.stats;
  const bool solved = run.status == PlannerStatus::solved;

  MotionValidator validator(problem.space, checker);
  Path path;
  double simplify_time = 0.0;
  if (solved) {
    path = run.path;
    if (!args.no_simplify) {
      const Stopwatch watch;
      Rng rng(spec.settings.seed ^ 0x9e3779b97f4a7c15ULL);
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

  const std::string mode(to_string(spec.mode));
  if (args.json) {
    nlohmann::json j;
    j["problem"] = problem.name;
    j["source"] = problem.source;
    j["mode"] = mode;
    j["status"] = std::string(to_string(run.status));
    j["solved"] = solved;
    j["seed"] = spec.settings.seed;
    j["range"] = run.range;
    j["extend"] = std::string(to_string(spec.settings.extend));
    j["time_limit_s"] = spec.time_limit;
    j["time_s"] = stats.time_s;
    j["iterations"] = stats.iterations;
    j["nodes"] = stats.nodes;
    j["edges"] = stats.edges;
    j["nodes_by_source"] = sources_json(stats);
    j["collision_checks"] = stats.collision_checks;
    j["tree_digest"] = format_digest(run.tree_digest);
    j["path_length"] =
        solved ? nlohmann::json(path_length(problem.space, path)) : nlohmann::json(nullptr);
    j["raw_path_length"] = solved ? nlohmann::json(run.path_length) : nlohmann::json(nullptr);
    j["path_states"] = path.size();
    j["simplify_time_s"] = simplify_time;
    j["out"] = solved && !args.out.empty() ? nlohmann::json(args.out) : nlohmann::json(nullptr);
    if (is_interactive(spec.mode)) {
      const InteractionSettings& i = spec.settings.interaction;
      j["operator"] = run.operator_description;
      j["operator_seed"] = spec.operator_seed;
      j["alpha"] = i.alpha;
      j["operator_iterations"] = stats.operator_iterations;
      j["operator_time_s"] = stats.operator_time_s;
      j["operator_waits"] = run.operator_waits;
      if (spec.mode == PlannerMode::interactive_contact) {
        j["contact_samples"] = i.contact_samples;
        j["contact_distance"] = contact_distance(i, problem.space);
        j["contact_entries"] = stats.contact_entries;
      }
      if (spec.mode == PlannerMode::irrt) {
        j["sampling"] = std::string(to_string(i.sampling));
        j["sigma"] = sigma_translation(i, problem.space);
        j["force_mix"] = i.force_mix;
        j["extensions"] = {{"collision", stats.extensions_collision},
                           {"reached", stats.extensions_reached},
                           {"obstacle", stats.extensions_obstacle}};
      }
    }
    std::cout << j.dump() << '\n';
  } else {
    std::cout << problem.name << ": "
              << (solved ? "solved" : "not solved (" + std::string(to_string(run.status)) + ")")
              << " by " << mode << " in " << stats.time_s << " s, " << stats.iterations
              << " iterations, " << stats.nodes << " nodes, " << stats.collision_checks
              << " collision checks (seed " << spec.settings.seed << ")\n";
    if (is_interactive(spec.mode)) {
      std::cout << "operator: " << run.operator_description << "; nodes from random samples "
                << stats.nodes_by_source[static_cast<std::size_t>(NodeSource::random)]
                << ", operator "
                << stats.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)]
                << ", contact "
                << stats.nodes_by_source[static_cast<std::size_t>(NodeSource::contact)] << '\n';
    }
    if (solved) {
      std::cout << "path: " << path.size() << " states, length " << path_length(problem.space, path)
                << " (before simplification " << run.path_length << ")";
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
  add_run_options(app, args->run);

  app.add_option("--out", args->out, "Write the path here, in OMPL's path format");
  app.add_option("--svg", args->svg, "Draw the problem and the path into this SVG file");
  app.add_flag("--json", args->json, "Print one JSON object with the run's figures");
  app.add_flag("--no-simplify", args->no_simplify, "Keep the path as the planner found it");
  app.footer(
      "The path is simplified (shortcuts), checked as read back from its file, then written.\n"
      "--json prints: problem, source, mode, status, solved, seed, range, extend, time_limit_s, "
      "time_s,\niterations, nodes, edges, nodes_by_source (root, random, operator, contact), "
      "collision_checks,\ntree_digest, path_length, raw_path_length, path_states, simplify_time_s, "
      "out; in "
      "interactive modes also operator,\noperator_seed, alpha, operator_iterations, "
      "operator_waits, "
      "operator_time_s and the mode's own figures.\nExit 0 if solved; 1 if not solved within the "
      "time limit; 2 for bad input (including a start or\ngoal outside the bounds or in "
      "collision).");
  return [args] { return run_plan(*args); };
}

}  // namespace tandem::cli
