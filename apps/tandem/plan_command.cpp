// tandem plan: solve a problem with the computer alone or with a (simulated) operator.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "plan_run.hpp"
#include "run_options.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/core/text.hpp"
#include "tandem/io/json_codec.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/render/svg_render.hpp"
#include "tandem/runs/portfolio.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/runs/run_record.hpp"

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

/// The tunables the planner read, at top level, with the scene-scaled values resolved.
void add_settings(nlohmann::json& j, const std::map<std::string, ParamValue>& tunables,
                  const Problem& problem, const RunSpec& spec, const RunOutcome& run) {
  for (const auto& [name, value] : tunables)
    j[name] = param_json(value);
  const InteractionSettings& i = spec.settings.interaction;
  j["range"] = run.range;
  if (j.contains("contact_distance"))
    j["contact_distance"] = contact_distance(i, problem.space);
  if (j.contains("contact_clearance"))
    j["contact_clearance"] = contact_clearance(i, problem.space, spec.settings.validation);
  if (j.contains("sigma"))
    j["sigma"] = sigma_translation(i, problem.space);
}

nlohmann::json plan_json(const PlanArgs& args, const Problem& problem, const PlanRun& planned) {
  const RunSpec& spec = planned.spec;
  const RunOutcome& run = planned.run;
  const bool solved = run.status == PlannerStatus::solved;
  const std::map<std::string, ParamValue> tunables = used_tunables(spec);
  nlohmann::json j = record_json(make_record(problem.name, spec.mode, tunables, spec.settings.seed,
                                             spec.time_limit, run, solved));
  j["source"] = problem.source;
  j["mode"] = spec.mode;
  j["member_planner"] = run.member_planner;
  add_settings(j, tunables, problem, spec, run);
  j["path_length"] = solved ? nlohmann::json(path_length(problem.space, planned.path)) : nullptr;
  j["raw_path_length"] = solved ? nlohmann::json(run.path_length) : nullptr;
  j["path_states"] = planned.path.size();
  j["simplify_time_s"] = planned.simplify_time_s;
  j["out"] = solved && !args.out.empty() ? nlohmann::json(args.out) : nullptr;
  if (uses_operator(spec)) {
    j["operator"] = run.operator_description;
    j["operator_seed"] = spec.operator_seed;
    j["operator_time_s"] = run.stats.operator_time_s;
    j["extensions"] = {{"collision", run.stats.extensions_collision},
                       {"reached", run.stats.extensions_reached},
                       {"obstacle", run.stats.extensions_obstacle}};
  }
  return j;
}

void print_summary(const PlanArgs& args, const Problem& problem, const PlanRun& planned) {
  const RunSpec& spec = planned.spec;
  const RunOutcome& run = planned.run;
  const PlannerStats& stats = run.stats;
  const bool solved = run.status == PlannerStatus::solved;
  std::cout << problem.name << ": "
            << (solved ? "solved" : "not solved (" + std::string(to_string(run.status)) + ")")
            << " by " << spec.mode << " in " << stats.time_s << " s, " << stats.iterations
            << " iterations, " << stats.nodes << " nodes, " << stats.collision_checks
            << " collision checks (seed " << spec.settings.seed;
  if (run.threads > 1) {
    std::cout << ", best of " << run.threads << " searches on as many threads: member "
              << run.member << ", " << run.member_planner;
  }
  std::cout << ")\n";
  if (uses_operator(spec)) {
    std::cout << "operator: " << run.operator_description << "; nodes from random samples "
              << stats.nodes_by_source[static_cast<std::size_t>(NodeSource::random)]
              << ", operator "
              << stats.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)]
              << ", contact "
              << stats.nodes_by_source[static_cast<std::size_t>(NodeSource::contact)] << '\n';
  }
  if (solved) {
    std::cout << "path: " << planned.path.size() << " states, length "
              << path_length(problem.space, planned.path) << " (before simplification "
              << run.path_length << ")";
    if (!args.out.empty())
      std::cout << ", written to " << args.out;
    std::cout << '\n';
  }
  if (!args.svg.empty())
    std::cout << "picture: " << args.svg << '\n';
}

int run_plan(const PlanArgs& args) {
  require_writable(args.out);
  require_writable(args.svg);
  const Problem problem = load_problem(args.run.problem);
  const PlanRun planned = plan_run(problem, args.run, !args.no_simplify);
  const bool solved = planned.run.status == PlannerStatus::solved;
  if (solved && !args.out.empty())
    write_path_file(args.out, planned.path, problem.space);
  if (!args.svg.empty())
    write_file_atomically(args.svg, render_svg(problem, planned.path));
  if (args.json)
    std::cout << plan_json(args, problem, planned).dump() << '\n';
  else
    print_summary(args, problem, planned);
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
      "--json prints a run record (as tandem bench records it: problem, config, params, seed,\n"
      "time_limit_s, status, solved, path_valid, time_s, iterations, nodes, edges, "
      "collision_checks,"
      "\nnodes_by_source, operator_iterations, contact_entries, operator_waits, tree_digest) and\n"
      "source, mode, every tunable the planner read (scene-scaled values resolved), path_length,\n"
      "raw_path_length, path_states, simplify_time_s, out; with an operator also operator,\n"
      "operator_seed, operator_time_s and the extensions' outcomes.\nExit 0 if solved; 1 if not "
      "solved within the "
      "time limit; 2 for bad input (including a start or\ngoal outside the bounds or in "
      "collision).");
  return [args] { return run_plan(*args); };
}

}  // namespace tandem::cli
