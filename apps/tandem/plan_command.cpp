// tandem plan: solve a problem with the computer alone or with a (simulated) operator.

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
#include "tandem/experiments/run.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/io/text.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/render/svg_render.hpp"

namespace tandem::cli {
namespace {

struct PlanArgs {
  ProblemArgs problem;
  std::optional<std::string> planner;
  std::optional<std::string> mode;
  std::optional<std::uint64_t> seed;
  std::optional<double> time_limit;
  std::optional<double> range;
  std::optional<double> goal_bias;
  std::optional<std::string> extend;
  // The human loop.
  std::string operator_name = "experienced";
  double operator_speed = 1.0;
  std::optional<std::uint64_t> operator_seed;
  std::uint64_t operator_period = 10;
  std::optional<double> alpha;
  int contact_samples = 10;
  double contact_distance = 0.0;
  std::string sampling = "mag";
  double sigma = 0.0;
  double force_mix = 0.5;
  int neighbours = 10;
  int uniform_every = 10;
  // Output.
  std::string out;
  std::string svg;
  bool json = false;
  bool no_simplify = false;
};

constexpr double kDefaultTimeLimit = 60.0;
/// The papers' authority sharing when the operator takes part (Blin et al. 2016: alpha = 0.5).
constexpr double kDefaultInteractiveAlpha = 0.5;

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

RunSpec make_spec(const PlanArgs& args, const Problem& problem) {
  RunSpec spec;
  // --mode, else --planner, else the problem's planner.
  if (args.mode && args.planner)
    throw InputError("--mode", "give --mode or --planner, not both");
  const std::string mode =
      args.mode.value_or(args.planner.value_or(problem.hints.planner.value_or("birrt")));
  spec.mode = *parse_planner_mode(mode);
  const std::string range_key = spec.mode == PlannerMode::rrt ? "rrt" : "birrt";

  PlannerSettings& s = spec.settings;
  s.seed = args.seed.value_or(problem.hints.seed.value_or(1));
  if (args.range) {
    s.range = *args.range;
  } else if (auto it = problem.hints.range.find(range_key); it != problem.hints.range.end()) {
    s.range = it->second;
  }
  s.goal_bias = args.goal_bias.value_or(problem.hints.goal_bias.value_or(s.goal_bias));
  s.extend = *parse_extend_mode(args.extend.value_or(problem.hints.extend.value_or("classic")));
  spec.time_limit = args.time_limit.value_or(problem.hints.time_limit.value_or(kDefaultTimeLimit));

  InteractionSettings& i = s.interaction;
  i.alpha = args.alpha.value_or(is_interactive(spec.mode) ? kDefaultInteractiveAlpha : 1.0);
  if (args.alpha && !is_interactive(spec.mode)) {
    throw InputError("--alpha",
                     "needs an interactive mode (--mode interactive or interactive-contact)");
  }
  i.contact_samples = args.contact_samples;
  i.contact_distance = args.contact_distance;
  i.sampling = *parse_irrt_sampling(args.sampling);
  i.sigma = args.sigma;
  i.force_mix = args.force_mix;
  i.neighbours = args.neighbours;
  i.uniform_every = args.uniform_every;

  spec.operator_name = args.operator_name;
  spec.operator_speed = args.operator_speed;
  spec.operator_seed = args.operator_seed.value_or(s.seed);
  spec.operator_period = args.operator_period;
  return spec;
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
  const Problem problem = load_problem(args.problem);
  const RunSpec spec = make_spec(args, problem);

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
  add_problem_args(app, args->problem);
  app.add_option(
         "--mode", args->mode,
         "birrt (the computer alone, default), rrt, interactive (authority sharing, Blin et "
         "al. 2016 Alg. 1), interactive-contact (with contact sampling, Alg. 3) or irrt "
         "(Taix & Flavigne 2011)")
      ->check(CLI::IsMember(planner_mode_names()));
  app.add_option("--planner", args->planner, "Planner without an operator: birrt (default) or rrt")
      ->check(CLI::IsMember({"birrt", "rrt"}));
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
                 "RRT's and the I-RRT's probability of extending toward the goal (default 0.05)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--extend", args->extend,
                 "How a tree grows toward a target it cannot reach: classic (all or nothing; the "
                 "default unless the problem says otherwise) or last-valid (keep the last valid "
                 "configuration, the papers' Add_Tree)")
      ->check(CLI::IsMember({"classic", "last-valid"}));

  const char* human = "Human loop";
  app.add_option(
         "--operator", args->operator_name,
         "The operator in interactive modes: experienced (default) or inexperienced, following "
         "the problem's [guide] in virtual time, or trace:FILE (a recorded trace in ticks)")
      ->group(human);
  app.add_option("--operator-speed", args->operator_speed,
                 "Multiplies the simulated operator's speed along the guide (default 1)")
      ->check(CLI::PositiveNumber)
      ->group(human);
  app.add_option("--operator-seed", args->operator_seed,
                 "Seed of the simulated operator's tremor and hesitation (default: --seed)")
      ->check(CLI::NonNegativeNumber)
      ->group(human);
  app.add_option("--operator-period", args->operator_period,
                 "Planner iterations per operator update in virtual time (default 10)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}))
      ->group(human);
  app.add_option("--alpha", args->alpha,
                 "Authority sharing: the probability that the computer (a uniform sample) has "
                 "authority in an iteration (default 0.5 in interactive modes)")
      ->check(CLI::Range(0.0, 1.0))
      ->group(human);
  app.add_option("--contact-samples", args->contact_samples,
                 "N: samples on the tangent plane each time contact mode is entered (default 10)")
      ->check(CLI::Range(1, 100000))
      ->group(human);
  app.add_option("--contact-distance", args->contact_distance,
                 "d: contact mode within this distance of an obstacle (default 1.5% of the bounds' "
                 "diagonal)")
      ->check(CLI::PositiveNumber)
      ->group(human);
  app.add_option("--sampling", args->sampling,
                 "I-RRT sampling mode: mag (around the user, default), path (around the user's "
                 "path), mag+cs, path+cs (with uniform samples)")
      ->check(CLI::IsMember({"mag", "path", "mag+cs", "path+cs"}))
      ->group(human);
  app.add_option("--sigma", args->sigma,
                 "I-RRT: standard deviation of the Gaussian shooting area (default 2% of the "
                 "bounds' diagonal)")
      ->check(CLI::PositiveNumber)
      ->group(human);
  app.add_option("--force-mix", args->force_mix,
                 "I-RRT: F_r = mix F_u + (1 - mix) F_a (the 2011 paper's alpha; default 0.5)")
      ->check(CLI::Range(0.0, 1.0))
      ->group(human);
  app.add_option("--neighbours", args->neighbours,
                 "I-RRT: p, nodes near the user for the centre of mass (default 10)")
      ->check(CLI::Range(1, 10000))
      ->group(human);
  app.add_option("--uniform-every", args->uniform_every,
                 "I-RRT +CS modes: one uniform sample every x shots (default 10)")
      ->check(CLI::Range(1, 1000000))
      ->group(human);

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
