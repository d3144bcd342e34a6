#include "run_options.hpp"

#include "tandem/core/error.hpp"
#include "tandem/interaction/interaction_settings.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem::cli {
namespace {

constexpr double kDefaultTimeLimit = 60.0;

/// "<help> (default D; R)" for a tunable's option.
std::string option_help(const Param<RunSpec>& p) {
  std::string h(p.spec.help);
  const ParamValue base = p.get(RunSpec{});
  h += " (default " + format_param(base);
  // Planners whose preset starts from another value (interactive-contact: contact on).
  for (const PlannerEntry& e : planner_registry()) {
    RunSpec preset;
    preset.settings = default_settings(e.name);
    if (const ParamValue v = p.get(preset); v != base)
      h += ", " + format_param(v) + " for " + std::string(e.name);
  }
  if (p.spec.kind == ParamKind::real || p.spec.kind == ParamKind::integer ||
      p.spec.kind == ParamKind::choice)
    h += "; " + describe_range(p.spec);
  if (!p.spec.group.empty())
    h += "; for " + planner_users(p.spec);
  return h + ")";
}

std::string mode_help() {
  std::string h = "The planner:";
  for (const PlannerEntry& e : planner_registry())
    h += "\n  " + std::string(e.name) + ": " + std::string(e.description);
  return h + "\n(default: the problem's, else " + std::string(kMixedPortfolio) +
         ", which on one thread is birrt)";
}

}  // namespace

RunSpec make_spec(const RunArgs& args, const Problem& problem) {
  if (args.mode && args.planner)
    throw InputError("--mode", "give --mode or --planner, not both");
  const std::string mode = args.mode.value_or(
      args.planner.value_or(problem.hints.planner.value_or(std::string(kMixedPortfolio))));
  // --mode and --planner are checked by the options, the problem's planner by check_hints.
  RunSpec spec = default_spec(mode, problem.hints);
  if (args.seed)
    spec.settings.seed = *args.seed;
  spec.operator_seed = args.operator_seed.value_or(spec.settings.seed);
  spec.time_limit = args.time_limit.value_or(problem.hints.time_limit.value_or(kDefaultTimeLimit));
  for (const auto& [name, text] : args.tunables) {
    const Param<RunSpec>& p = *find_param(run_tunables(), name);
    const ParamValue value = parse_param_option(p.spec, text);
    require_used(spec, name, p.spec.option());
    p.set(spec, value);
  }
  return spec;
}

void add_run_options(CLI::App& app, RunArgs& args) {
  add_problem_args(app, args.problem);
  app.add_option("--mode", args.mode, mode_help())->check(CLI::IsMember(planner_names()));
  app.add_option("--planner", args.planner, "The same as --mode")
      ->check(CLI::IsMember(planner_names()));
  app.add_option("--seed", args.seed,
                 "Random seed (default: the problem's, else 1); same seed, same path")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--time-limit", args.time_limit,
                 "Seconds before giving up (default: the problem's, else 60)")
      ->check(CLI::PositiveNumber);
  const char* human = "Human loop";
  app.add_option("--operator-seed", args.operator_seed,
                 "Seed of the simulated operator's tremor and hesitation (default: --seed)")
      ->check(CLI::NonNegativeNumber)
      ->group(human);
  for (const Param<RunSpec>& p : run_tunables()) {
    const std::string name(p.spec.name);
    auto* option = app.add_option_function<std::string>(
        p.spec.option(), [&args, name](const std::string& text) { args.tunables[name] = text; },
        option_help(p));
    static constexpr const char* kTypes[] = {"REAL", "INT", "BOOL", "CHOICE", "TEXT"};
    option->type_name(kTypes[static_cast<std::size_t>(p.spec.kind)]);
    if (find_param(planner_parameters(), name) == nullptr)
      option->group(human);
  }
}

}  // namespace tandem::cli
